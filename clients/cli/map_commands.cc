// map save / load / list / delete: the mapping service's store of named maps.
#include <iostream>

#include "absl/time/time.h"
#include "clients/cli/call.h"
#include "clients/cli/command.h"
#include "clients/cli/core/exit_codes.h"
#include "clients/cli/core/table.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"

namespace semnav::cli {
namespace {

namespace api = ::semnav::mapping::v1;
using MappingStub = api::MappingService::Stub;

std::string SavedTime(int64_t saved_ns) {
  return absl::FormatTime("%Y-%m-%dT%H:%M:%SZ", absl::FromUnixNanos(saved_ns), absl::UTCTimeZone());
}

std::string MapLine(const api::MapInfo& map) {
  return absl::StrCat(map.map_id(), "  ", map.size_bytes(), " bytes  saved ", SavedTime(map.saved_ns()));
}

// save, load and delete: a request id and a map id in, a message out.
template <typename Request, typename Response>
int Transact(const Invocation& invocation,
             absl::Status (*call)(const Invocation&, MappingStub&, const Request&, Response*),
             const std::function<std::string(const Request&, const Response&)>& describe) {
  Request request;
  request.set_request_id(invocation.RequestId());
  request.set_map_id(invocation.positional()[0]);
  return WithStub<api::MappingService>(invocation, Service::kMapping, [&](MappingStub& stub) {
    Response response;
    if (absl::Status s = call(invocation, stub, request, &response); !s.ok()) return Fail(s);
    if (invocation.json()) {
      PrintJson(response);
    } else {
      std::cout << describe(request, response) << std::endl;
    }
    return ToInt(ExitCode::kOk);
  });
}

template <auto Method, typename Request, typename Response>
absl::Status Call(const Invocation& invocation, MappingStub& stub, const Request& request, Response* response) {
  return CallUnary(invocation, stub, Method, request, response);
}

int List(const Invocation& invocation) {
  return WithStub<api::MappingService>(invocation, Service::kMapping, [&](MappingStub& stub) {
    api::ListMapsResponse response;
    if (auto s = CallUnary(invocation, stub, &MappingStub::ListMaps, api::ListMapsRequest(), &response); !s.ok()) {
      return Fail(s);
    }
    if (invocation.json()) {
      PrintJson(response);
      return ToInt(ExitCode::kOk);
    }
    Table table({"MAP", "BYTES", "SAVED"});
    for (const api::MapInfo& map : response.maps()) {
      table.AddRow({map.map_id(), std::to_string(map.size_bytes()), SavedTime(map.saved_ns())});
    }
    std::cout << table.Render();
    return ToInt(ExitCode::kOk);
  });
}

}  // namespace

std::vector<Command> MapCommands() {
  return {
      {"map", "save", "MAP_ID", "write the live map to the store (replaces a map of that name)", Service::kMapping,
       {kRequestIdFlag},
       [](const Invocation& i) {
         return Transact<api::SaveMapRequest, api::SaveMapResponse>(
             i, Call<&MappingStub::SaveMap, api::SaveMapRequest, api::SaveMapResponse>,
             [](const api::SaveMapRequest&, const api::SaveMapResponse& r) { return "saved " + MapLine(r.map()); });
       },
       1},
      {"map", "load", "MAP_ID", "replace the live map by a stored one", Service::kMapping, {kRequestIdFlag},
       [](const Invocation& i) {
         return Transact<api::LoadMapRequest, api::LoadMapResponse>(
             i, Call<&MappingStub::LoadMap, api::LoadMapRequest, api::LoadMapResponse>,
             [](const api::LoadMapRequest&, const api::LoadMapResponse& r) {
               return absl::StrCat("loaded ", MapLine(r.map()), "  live revision ", r.revision());
             });
       },
       1},
      {"map", "list", "", "maps in the store", Service::kMapping, {}, List, 0},
      {"map", "delete", "MAP_ID", "remove a stored map", Service::kMapping, {kRequestIdFlag},
       [](const Invocation& i) {
         return Transact<api::DeleteMapRequest, api::DeleteMapResponse>(
             i, Call<&MappingStub::DeleteMap, api::DeleteMapRequest, api::DeleteMapResponse>,
             [](const api::DeleteMapRequest& q, const api::DeleteMapResponse&) { return "deleted " + q.map_id(); });
       },
       1},
  };
}

}  // namespace semnav::cli

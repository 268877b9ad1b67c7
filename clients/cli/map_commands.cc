// map save / load / list / delete: the mapping service's store of named maps.
#include "absl/time/time.h"
#include "clients/cli/call.h"
#include "clients/cli/command.h"
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
  return absl::StrCat(map.map_id(), "  ", map.size_bytes(), " bytes  saved ",
                      SavedTime(map.saved_ns()));
}

// save, load and delete: a request id and the map id argument in.
template <typename Request, typename Response, typename Describe>
int Transact(const Invocation& invocation,
             grpc::Status (MappingStub::*method)(grpc::ClientContext*, const Request&, Response*),
             Describe describe) {
  Request request;
  request.set_request_id(invocation.RequestId());
  request.set_map_id(invocation.positional()[0]);
  return RunUnary<api::MappingService>(
      invocation, Service::kMapping, method, request,
      [&](const Response& response) { return describe(request, response); });
}

int List(const Invocation& invocation) {
  return RunUnary<api::MappingService>(
      invocation, Service::kMapping, &MappingStub::ListMaps, api::ListMapsRequest(),
      [](const api::ListMapsResponse& r) {
        Table table({"MAP", "BYTES", "SAVED"});
        for (const api::MapInfo& map : r.maps()) {
          table.AddRow({map.map_id(), std::to_string(map.size_bytes()), SavedTime(map.saved_ns())});
        }
        return table.Render();
      });
}

}  // namespace

std::vector<Command> MapCommands() {
  return {
      {"map",
       "save",
       "MAP_ID",
       "write the live map to the store (replaces a map of that name)",
       Service::kMapping,
       {kRequestIdFlag},
       [](const Invocation& i) {
         return Transact(i, &MappingStub::SaveMap,
                         [](const api::SaveMapRequest&, const api::SaveMapResponse& r) {
                           return "saved " + MapLine(r.map()) + "\n";
                         });
       },
       1},
      {"map",
       "load",
       "MAP_ID",
       "replace the live map by a stored one",
       Service::kMapping,
       {kRequestIdFlag},
       [](const Invocation& i) {
         return Transact(i, &MappingStub::LoadMap,
                         [](const api::LoadMapRequest&, const api::LoadMapResponse& r) {
                           return absl::StrCat("loaded ", MapLine(r.map()), "  live revision ",
                                               r.revision(), "\n");
                         });
       },
       1},
      {"map", "list", "", "maps in the store", Service::kMapping, {}, List, 0},
      {"map",
       "delete",
       "MAP_ID",
       "remove a stored map",
       Service::kMapping,
       {kRequestIdFlag},
       [](const Invocation& i) {
         return Transact(i, &MappingStub::DeleteMap,
                         [](const api::DeleteMapRequest& q, const api::DeleteMapResponse&) {
                           return "deleted " + q.map_id() + "\n";
                         });
       },
       1},
  };
}

}  // namespace semnav::cli

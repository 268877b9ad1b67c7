// reloc upsert / show / relocalize / delete: landmark maps of the relocalization service.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "clients/cli/call.h"
#include "clients/cli/command.h"
#include "clients/cli/core/exit_codes.h"
#include "clients/cli/core/table.h"
#include "semnav/relocalization/v1/relocalization.grpc.pb.h"

namespace semnav::cli {
namespace {

namespace api = ::semnav::relocalization::v1;
using RelocStub = api::RelocalizationService::Stub;

const FlagSpec kMapFlag = {"map-id", "MAP_ID", "landmark map (required)"};

std::string Vector(const common::v1::Vector3& v) {
  return absl::StrCat("(", FormatFixed(v.x(), 3), ", ", FormatFixed(v.y(), 3), ", ",
                      FormatFixed(v.z(), 3), ")");
}

double YawDegrees(const common::v1::Quaternion& q) {
  return std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()),
                    1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z())) *
         180.0 / M_PI;
}

std::string DescribeSolution(const api::PoseSolution& solution) {
  std::string out = absl::StrCat(
      "translation ", Vector(solution.map_from_query().position()), " m  yaw ",
      FormatFixed(YawDegrees(solution.map_from_query().orientation()), 2), " deg\n",
      solution.inlier_count(), " inliers, rms ", FormatFixed(solution.rms_residual_m(), 4),
      " m, reliable ", solution.reliable() ? "yes" : "no", "\n\n");
  Table matches({"QUERY", "MAP_LANDMARK", "SIMILARITY", "INLIER"});
  for (const api::LandmarkMatch& match : solution.matches()) {
    matches.AddRow({std::to_string(match.query_index()), std::to_string(match.map_landmark_id()),
                    FormatFixed(match.similarity(), 3), match.inlier() ? "yes" : "no"});
  }
  return out + matches.Render();
}

// Reads --FILE_FLAG's JSON into `request` and sets map_id from --map-id.
template <typename Request>
absl::Status LoadRequest(const Invocation& invocation, const std::string& file_flag,
                         Request& request) {
  if (!invocation.Has("map-id") || !invocation.Has(file_flag)) {
    return absl::InvalidArgumentError(absl::StrCat("needs --map-id and --", file_flag));
  }
  if (absl::Status read = ReadJsonFile(file_flag, invocation.Flag(file_flag), &request); !read.ok())
    return read;
  request.set_map_id(invocation.Flag("map-id"));
  return absl::OkStatus();
}

int Upsert(const Invocation& invocation) {
  api::UpsertLandmarksRequest request;
  if (absl::Status s = LoadRequest(invocation, "landmarks", request); !s.ok())
    return UsageError(std::string(s.message()));
  request.set_request_id(invocation.RequestId());
  return RunUnary<api::RelocalizationService>(
      invocation, Service::kRelocalization, &RelocStub::UpsertLandmarks, request,
      [&](const api::UpsertLandmarksResponse& r) {
        return absl::StrCat(request.map_id(), " revision ", r.revision(), ": ", r.inserted(),
                            " inserted, ", r.merged(), " merged, ", r.replaced(), " replaced; ids ",
                            absl::StrJoin(r.landmark_ids(), " "), "\n");
      });
}

int Show(const Invocation& invocation) {
  if (!invocation.Has("map-id")) return UsageError("reloc show needs --map-id");
  api::GetLandmarkMapRequest request;
  request.set_map_id(invocation.Flag("map-id"));
  return WithStub<api::RelocalizationService>(
      invocation, Service::kRelocalization, [&](RelocStub& stub) {
        grpc::ClientContext context;
        invocation.SetDeadline(context, kDefaultUnaryDeadline);
        auto reader = stub.GetLandmarkMap(&context, request);
        Table table({"ID", "X", "Y", "Z", "SCALE_M", "OBS", "LABEL"});
        api::GetLandmarkMapResponse page;
        uint64_t revision = 0;
        uint32_t total = 0;
        while (reader->Read(&page)) {
          revision = page.revision();
          total = page.total_landmarks();
          if (invocation.json()) PrintJson(page);
          for (const api::Landmark& landmark : page.landmarks()) {
            const auto best =
                std::max_element(landmark.embedding().begin(), landmark.embedding().end());
            table.AddRow(
                {std::to_string(landmark.id()), FormatFixed(landmark.position().x(), 3),
                 FormatFixed(landmark.position().y(), 3), FormatFixed(landmark.position().z(), 3),
                 FormatFixed(landmark.scale_m(), 3), std::to_string(landmark.observations()),
                 best == landmark.embedding().end()
                     ? ""
                     : std::to_string(best - landmark.embedding().begin())});
          }
        }
        if (grpc::Status finished = reader->Finish(); !finished.ok())
          return Fail(FromGrpcStatus(finished));
        if (!invocation.json()) {
          std::cout << request.map_id() << " revision " << revision << ": " << total
                    << " landmarks\n\n"
                    << table.Render();
        }
        return ToInt(ExitCode::kOk);
      });
}

int Relocalize(const Invocation& invocation) {
  api::RelocalizeRequest request;
  if (absl::Status s = LoadRequest(invocation, "observed", request); !s.ok())
    return UsageError(std::string(s.message()));
  return RunUnary<api::RelocalizationService>(
      invocation, Service::kRelocalization, &RelocStub::Relocalize, request,
      [&](const api::RelocalizeResponse& r) {
        return absl::StrCat("relocalized in ", request.map_id(), " (revision ", r.map_revision(),
                            ")\n", DescribeSolution(r.solution()));
      });
}

int Delete(const Invocation& invocation) {
  if (!invocation.Has("map-id")) return UsageError("reloc delete needs --map-id");
  api::DeleteLandmarkMapRequest request;
  request.set_map_id(invocation.Flag("map-id"));
  request.set_request_id(invocation.RequestId());
  return RunUnary<api::RelocalizationService>(
      invocation, Service::kRelocalization, &RelocStub::DeleteLandmarkMap, request,
      [&](const api::DeleteLandmarkMapResponse&) {
        return absl::StrCat("deleted ", request.map_id(), "\n");
      });
}

}  // namespace

std::vector<Command> RelocalizationCommands() {
  return {
      {"reloc",
       "relocalize",
       "",
       "pose of observed landmarks (JSON file of a RelocalizeRequest's \"observed\" list) in a "
       "landmark map",
       Service::kRelocalization,
       {kMapFlag,
        {"observed", "FILE",
         "JSON {\"observed\": [Landmark...]} in the robot's odometry frame (required)"}},
       Relocalize,
       0},
      {"reloc",
       "upsert",
       "",
       "add landmarks to a map (JSON file {\"landmarks\": [Landmark...]})",
       Service::kRelocalization,
       {kMapFlag, {"landmarks", "FILE", "JSON {\"landmarks\": [...]} (required)"}, kRequestIdFlag},
       Upsert,
       0},
      {"reloc",
       "show",
       "",
       "a landmark map as a table",
       Service::kRelocalization,
       {kMapFlag},
       Show,
       0},
      {"reloc",
       "delete",
       "",
       "delete a landmark map",
       Service::kRelocalization,
       {kMapFlag, kRequestIdFlag},
       Delete,
       0},
  };
}

}  // namespace semnav::cli

#include "services/relocalization/server/relocalization_service.h"

#include <algorithm>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/strip.h"
#include "services/common/status/field_error.h"
#include "services/common/status/grpc_status.h"
#include "services/common/status/value_checks.h"
#include "services/relocalization/core/indexed_landmarks.h"
#include "services/relocalization/core/object_points.h"
#include "services/relocalization/core/relocalizer.h"
#include "services/relocalization/server/image_decode.h"
#include "services/relocalization/server/proto_convert.h"

namespace semnav::relocalization {
namespace {

constexpr uint32_t kDefaultPageSize = 1000;
// Request limits (docs/protocol.md): a page of this many 4096-float landmarks stays a few
// hundred MB at worst; the usual 16-float ones ~1 MB, within the 4 MiB message limit.
constexpr uint32_t kMaxPageSize = 10000;
constexpr uint32_t kMaxTopK = 100000;
// Pixels per side of an image for the detector; larger images are rejected before decoding.
constexpr uint32_t kMaxImageSide = 8192;

// Idempotency keys are kept in a cache: bounded like every other id.
absl::Status CheckRequestId(const std::string& request_id) {
  return CheckLength(request_id, "request_id", kMaxIdBytes);
}

grpc::ServerUnaryReactor* Answer(grpc::CallbackServerContext* context, const absl::Status& status) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(ToGrpcStatus(status));
  return reactor;
}

std::vector<uint64_t> IdsOf(const LandmarkMap& map) {
  std::vector<uint64_t> ids;
  ids.reserve(map.landmarks().size());
  for (const Landmark& l : map.landmarks()) ids.push_back(l.id);
  return ids;
}

// Streams a map snapshot in pages; owns itself until OnDone.
class MapPageWriter final : public grpc::ServerWriteReactor<v1::GetLandmarkMapResponse> {
 public:
  MapPageWriter(std::shared_ptr<const LandmarkMap> map, uint32_t page_size)
      : map_(std::move(map)), page_size_(page_size == 0 ? kDefaultPageSize : page_size) {
    WriteNext();
  }
  void OnWriteDone(bool ok) override {
    if (!ok) {
      Finish(ToGrpcStatus(absl::CancelledError("client stopped reading")));
      return;
    }
    if (next_ >= map_->landmarks().size()) {
      Finish(grpc::Status::OK);
      return;
    }
    WriteNext();
  }
  void OnDone() override { delete this; }

 private:
  void WriteNext() {
    const std::vector<Landmark>& all = map_->landmarks();
    page_.Clear();
    page_.set_revision(map_->revision());
    page_.set_total_landmarks(static_cast<uint32_t>(all.size()));
    const size_t end = std::min(all.size(), next_ + page_size_);
    for (; next_ < end; ++next_) LandmarkToProto(all[next_], page_.add_landmarks());
    StartWrite(&page_);
  }

  const std::shared_ptr<const LandmarkMap> map_;
  const size_t page_size_;
  size_t next_ = 0;
  v1::GetLandmarkMapResponse page_;
};

// A reactor that fails at once (for errors found before streaming starts).
class FailedWriter final : public grpc::ServerWriteReactor<v1::GetLandmarkMapResponse> {
 public:
  explicit FailedWriter(const absl::Status& status) { Finish(ToGrpcStatus(status)); }
  void OnDone() override { delete this; }
};

}  // namespace

RelocalizationServiceImpl::RelocalizationServiceImpl(const ServiceConfig& config,
                                                     std::unique_ptr<LandmarkStore> store,
                                                     std::unique_ptr<OnnxHeads> detector)
    : config_(config),
      store_(std::move(store)),
      detector_(std::move(detector)),
      upsert_answers_(config.idempotency_cache),
      delete_answers_(config.idempotency_cache) {}

absl::StatusOr<std::shared_ptr<const LandmarkMap>> RelocalizationServiceImpl::GetMap(
    const std::string& map_id, absl::string_view field) const {
  absl::StatusOr<std::shared_ptr<const LandmarkMap>> map = store_->Get(map_id);
  if (map.ok()) return map;
  const absl::StatusCode code = map.status().code();
  const absl::string_view reason = code == absl::StatusCode::kNotFound   ? "MAP_NOT_FOUND"
                                   : code == absl::StatusCode::kDataLoss ? "MAP_CORRUPT"
                                                                         : "FIELD_INVALID";
  // The store names "map_id"; requests with two maps need the real field name.
  return WithReason(WithField(map.status(), field), reason);
}

absl::Status RelocalizationServiceImpl::DoExtract(const v1::ExtractObjectPointsRequest& request,
                                                  v1::ExtractObjectPointsResponse& response) {
  ObjectPointParams params = config_.object_points;
  if (request.top_k() > kMaxTopK) {
    return InvalidField("top_k", absl::StrCat("must be at most ", kMaxTopK));
  }
  if (request.top_k() != 0) params.top_k = static_cast<int>(request.top_k());
  HeadTensors heads;
  switch (request.input_case()) {
    case v1::ExtractObjectPointsRequest::kTensors:
      heads = HeadTensorsFromProto(request.tensors());
      break;
    case v1::ExtractObjectPointsRequest::kImage: {
      if (detector_ == nullptr) {
        return FieldError(absl::StatusCode::kFailedPrecondition, "image",
                          "no ONNX detector configured (relocalization.detector.model_path)",
                          "NO_DETECTOR");
      }
      // Before decoding: a small PNG can claim a huge raster.
      if (request.image().width() > kMaxImageSide) {
        return InvalidField("image.width", absl::StrCat("must be at most ", kMaxImageSide));
      }
      if (request.image().height() > kMaxImageSide) {
        return InvalidField("image.height", absl::StrCat("must be at most ", kMaxImageSide));
      }
      absl::StatusOr<cv::Mat> image = DecodeColorImage(request.image());
      if (!image.ok()) return image.status();
      absl::StatusOr<HeadTensors> computed = detector_->Run(*image);
      if (!computed.ok()) return WithErrorInfo(computed.status(), "DETECTOR_FAILED");
      heads = *std::move(computed);
      break;
    }
    default:
      return FieldError(absl::StatusCode::kInvalidArgument, "input", "set tensors or image");
  }
  absl::StatusOr<std::vector<ObjectPoint>> points =
      relocalization::ExtractObjectPoints(heads, params);
  if (!points.ok()) return WithErrorInfo(points.status(), "FIELD_INVALID");
  for (const ObjectPoint& p : *points) ObjectPointToProto(p, response.add_points());
  return absl::OkStatus();
}

absl::Status RelocalizationServiceImpl::DoUpsert(const v1::UpsertLandmarksRequest& request,
                                                 v1::UpsertLandmarksResponse& response) {
  if (absl::Status s = CheckRequestId(request.request_id()); !s.ok()) return s;
  absl::MutexLock lock(&transaction_mu_);
  if (auto first = upsert_answers_.Find(request.request_id())) {
    response = *std::move(first);
    return absl::OkStatus();
  }
  if (absl::Status s = ValidateMapId(request.map_id()); !s.ok())
    return WithErrorInfo(s, "FIELD_INVALID");
  if (request.landmarks().empty()) {
    return InvalidField("landmarks", "must contain at least one landmark");
  }
  size_t dim = 0;
  if (absl::StatusOr<std::shared_ptr<const LandmarkMap>> existing = store_->Get(request.map_id());
      existing.ok()) {
    dim = (*existing)->descriptor_dim();
  }
  absl::StatusOr<std::vector<Landmark>> landmarks =
      LandmarksFromProto(request.landmarks(), dim, "landmarks");
  if (!landmarks.ok()) return landmarks.status();
  absl::StatusOr<UpsertSummary> summary = store_->Upsert(request.map_id(), *std::move(landmarks));
  if (!summary.ok()) {
    const absl::StatusCode code = summary.status().code();
    return WithErrorInfo(summary.status(), code == absl::StatusCode::kDataLoss ? "MAP_CORRUPT"
                                           : code == absl::StatusCode::kNotFound
                                               ? "LANDMARK_NOT_FOUND"
                                               : "FIELD_INVALID");
  }
  response.set_revision(summary->revision);
  response.set_inserted(static_cast<uint32_t>(summary->inserted));
  response.set_merged(static_cast<uint32_t>(summary->merged));
  response.set_replaced(static_cast<uint32_t>(summary->replaced));
  response.mutable_landmark_ids()->Assign(summary->ids.begin(), summary->ids.end());
  upsert_answers_.Remember(request.request_id(), response);
  return absl::OkStatus();
}

absl::Status RelocalizationServiceImpl::DoDelete(const v1::DeleteLandmarkMapRequest& request) {
  if (absl::Status s = CheckRequestId(request.request_id()); !s.ok()) return s;
  absl::MutexLock lock(&transaction_mu_);
  if (delete_answers_.Find(request.request_id())) return absl::OkStatus();
  absl::Status s = store_->Delete(request.map_id());
  if (!s.ok()) {
    return WithErrorInfo(
        s, s.code() == absl::StatusCode::kNotFound ? "MAP_NOT_FOUND" : "FIELD_INVALID");
  }
  delete_answers_.Remember(request.request_id(), v1::DeleteLandmarkMapResponse());
  return absl::OkStatus();
}

absl::Status RelocalizationServiceImpl::DoRelocalize(const v1::RelocalizeRequest& request,
                                                     v1::RelocalizeResponse& response) {
  absl::StatusOr<std::shared_ptr<const LandmarkMap>> map = GetMap(request.map_id(), "map_id");
  if (!map.ok()) return map.status();
  if (request.observed().empty()) return InvalidField("observed", "must not be empty");
  absl::StatusOr<std::vector<Landmark>> observed =
      LandmarksFromProto(request.observed(), (*map)->descriptor_dim(), "observed");
  if (!observed.ok()) return observed.status();
  const std::shared_ptr<const IndexedLandmarks> index = (*map)->index();
  absl::StatusOr<RelocalizationResult> result = relocalization::Relocalize(
      IndexedLandmarks(*std::move(observed)), *index, config_.relocalization);
  if (!result.ok()) return WithErrorInfo(result.status(), "RELOCALIZATION_FAILED");
  SolutionToProto(*result, {}, IdsOf(**map), response.mutable_solution());
  response.set_map_revision((*map)->revision());
  return absl::OkStatus();
}

absl::Status RelocalizationServiceImpl::DoAlign(const v1::AlignMapsRequest& request,
                                                v1::AlignMapsResponse& response) {
  absl::StatusOr<std::shared_ptr<const LandmarkMap>> reference =
      GetMap(request.reference_map_id(), "reference_map_id");
  if (!reference.ok()) return reference.status();
  absl::StatusOr<std::shared_ptr<const LandmarkMap>> moving =
      GetMap(request.moving_map_id(), "moving_map_id");
  if (!moving.ok()) return moving.status();
  if ((*moving)->descriptor_dim() != (*reference)->descriptor_dim()) {
    return FieldError(
        absl::StatusCode::kInvalidArgument, "moving_map_id",
        absl::StrCat("descriptor length ", (*moving)->descriptor_dim(),
                     " differs from the reference map's ", (*reference)->descriptor_dim()));
  }
  absl::StatusOr<RelocalizationResult> result = relocalization::Relocalize(
      *(*moving)->index(), *(*reference)->index(), config_.relocalization);
  if (!result.ok()) return WithErrorInfo(result.status(), "ALIGNMENT_FAILED");
  SolutionToProto(*result, IdsOf(**moving), IdsOf(**reference), response.mutable_solution());
  response.set_reference_revision((*reference)->revision());
  response.set_moving_revision((*moving)->revision());
  return absl::OkStatus();
}

grpc::ServerUnaryReactor* RelocalizationServiceImpl::ExtractObjectPoints(
    grpc::CallbackServerContext* context, const v1::ExtractObjectPointsRequest* request,
    v1::ExtractObjectPointsResponse* response) {
  return Answer(context, DoExtract(*request, *response));
}

grpc::ServerUnaryReactor* RelocalizationServiceImpl::UpsertLandmarks(
    grpc::CallbackServerContext* context, const v1::UpsertLandmarksRequest* request,
    v1::UpsertLandmarksResponse* response) {
  return Answer(context, DoUpsert(*request, *response));
}

grpc::ServerWriteReactor<v1::GetLandmarkMapResponse>* RelocalizationServiceImpl::GetLandmarkMap(
    grpc::CallbackServerContext* /*context*/, const v1::GetLandmarkMapRequest* request) {
  if (request->page_size() > kMaxPageSize) {
    return new FailedWriter(
        InvalidField("page_size", absl::StrCat("must be at most ", kMaxPageSize)));
  }
  absl::StatusOr<std::shared_ptr<const LandmarkMap>> map = GetMap(request->map_id(), "map_id");
  if (!map.ok()) return new FailedWriter(map.status());
  return new MapPageWriter(*std::move(map), request->page_size());
}

grpc::ServerUnaryReactor* RelocalizationServiceImpl::DeleteLandmarkMap(
    grpc::CallbackServerContext* context, const v1::DeleteLandmarkMapRequest* request,
    v1::DeleteLandmarkMapResponse* /*response*/) {
  return Answer(context, DoDelete(*request));
}

grpc::ServerUnaryReactor* RelocalizationServiceImpl::Relocalize(
    grpc::CallbackServerContext* context, const v1::RelocalizeRequest* request,
    v1::RelocalizeResponse* response) {
  return Answer(context, DoRelocalize(*request, *response));
}

grpc::ServerUnaryReactor* RelocalizationServiceImpl::AlignMaps(grpc::CallbackServerContext* context,
                                                               const v1::AlignMapsRequest* request,
                                                               v1::AlignMapsResponse* response) {
  return Answer(context, DoAlign(*request, *response));
}

}  // namespace semnav::relocalization

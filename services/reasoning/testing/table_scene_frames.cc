#include "services/reasoning/testing/table_scene_frames.h"

#include <grpcpp/client_context.h>

#include "absl/strings/str_cat.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "services/mapping/testing/frame_proto.h"
#include "services/mapping/testing/synthetic_room.h"

namespace semnav::reasoning::testing {
namespace {

constexpr int64_t kFrameNs = 100'000'000;

mapping::CameraPose Viewpoint() {
  return mapping::testing::LookAt({0.5, 2.0, 1.2}, {4.0, 2.0, 0.0});
}

}  // namespace

mapping::v1::SensorFrame LabelledFrame(int64_t stamp_ns, const std::string& label,
                                       const Eigen::Vector3d& point) {
  mapping::v1::SensorFrame frame = mapping::testing::FrameToProto(
      mapping::testing::RenderFrame(mapping::testing::StandardRoom(), Viewpoint(), stamp_ns));
  const mapping::Intrinsics k = mapping::testing::Vga();
  const Eigen::Vector3d c = Viewpoint().orientation.conjugate() * (point - Viewpoint().position);
  const double u = k.fx * c.x() / c.z() + k.cx;
  const double v = k.fy * c.y() / c.z() + k.cy;
  mapping::v1::Detection* detection = frame.add_detections();
  detection->set_label(label);
  detection->set_score(0.9);
  detection->mutable_box()->set_x_min(u - 40);
  detection->mutable_box()->set_y_min(v - 40);
  detection->mutable_box()->set_x_max(u + 40);
  detection->mutable_box()->set_y_max(v + 40);
  return frame;
}

absl::Status StreamLabelledFrames(const std::shared_ptr<grpc::Channel>& mapping,
                                  int64_t first_index, int count, const std::string& label,
                                  const Eigen::Vector3d& point) {
  auto stub = mapping::v1::MappingService::NewStub(mapping);
  grpc::ClientContext context;
  auto stream = stub->StreamFrames(&context);
  for (int i = 0; i < count; ++i) {
    mapping::v1::StreamFramesRequest request;
    *request.mutable_frame() = LabelledFrame((first_index + i) * kFrameNs, label, point);
    mapping::v1::StreamFramesResponse response;
    if (!stream->Write(request) || !stream->Read(&response)) break;
    if (!response.ack().accepted()) {
      return absl::InternalError(
          absl::StrCat("frame rejected: ", response.ack().ShortDebugString()));
    }
  }
  stream->WritesDone();
  const grpc::Status status = stream->Finish();
  if (!status.ok())
    return absl::InternalError(absl::StrCat("StreamFrames: ", status.error_message()));
  return absl::OkStatus();
}

}  // namespace semnav::reasoning::testing

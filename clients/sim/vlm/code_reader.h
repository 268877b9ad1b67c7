// Reads the EROI codes the gateway printed into a camera image (white Hershey-simplex text on a
// black box, services/reasoning/core/inverse_mapping.cc), the way a VLM reads them: from the
// pixels. The printed boxes are where the received image differs from the frame the camera
// took; each box is read by rendering letter-digits-letter candidates of its width and keeping
// the one that reproduces its pixels. Boxes cut by the image border are not read.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace semnav::sim::vlm {

struct PrintedCode {
  std::string code;   // e.g. "G5A"
  cv::Rect box;       // pixels
  cv::Point2d pixel;  // the point the code labels (the box's text centre)
};

// `received` and `raw` are 8-bit BGR of one size. `font_scale` and `thickness` are the gateway's.
std::vector<PrintedCode> ReadPrintedCodes(const cv::Mat& received, const cv::Mat& raw,
                                          double font_scale, int thickness);

}  // namespace semnav::sim::vlm

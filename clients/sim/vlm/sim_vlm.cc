#include "clients/sim/vlm/sim_vlm.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "clients/sim/core/class_embedding.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/view_renderer.h"
#include "clients/sim/vlm/code_reader.h"
#include "nlohmann/json.hpp"
#include "services/common/lexicon/canonical_term.h"
#include "services/modelproxy/core/offline/open_vocabulary.h"

namespace semnav::sim::vlm {
namespace {

constexpr char kNothing[] = "No clue or passage.";

// The text between `open` and the next `close` after it; "" if absent.
std::string Between(absl::string_view text, absl::string_view open, absl::string_view close) {
  const size_t start = text.find(open);
  if (start == absl::string_view::npos) return "";
  const size_t from = start + open.size();
  const size_t end = text.find(close, from);
  if (end == absl::string_view::npos) return "";
  return std::string(text.substr(from, end - from));
}

// A stated latency: log-normal around `median` with the configured spread and cap, in whole
// milliseconds so the header value the endpoint sends is exact.
double DrawLatency(Rng& rng, double median, const SimVlmLatency& latency) {
  const double seconds = std::min(latency.max_s, median * std::exp(latency.sigma * rng.Normal()));
  return std::round(1000.0 * seconds) / 1000.0;
}

// A neighbouring cell's code: the letter or the number moved by one (never below 1 or 'A').
std::string OffByOne(const std::string& code, Rng& rng) {
  std::string letter = code.substr(0, 1);
  int number = std::atoi(code.substr(1, code.size() - 2).c_str());
  const std::string last = code.substr(code.size() - 1);
  const int step = rng.Bernoulli(0.5) ? 1 : -1;
  if (rng.Bernoulli(0.5)) {
    const char moved = static_cast<char>(letter[0] + step);
    letter[0] = moved < 'A' ? 'B' : moved > 'Z' ? 'Y' : moved;
  } else {
    number = number + step < 1 ? 2 : number + step;
  }
  return absl::StrCat(letter, number, last);
}

const PrintedCode* Nearest(const std::vector<PrintedCode>& codes, const cv::Point2d& pixel) {
  const PrintedCode* best = nullptr;
  double best_d = 0;
  for (const PrintedCode& code : codes) {
    const double d = std::hypot(code.pixel.x - pixel.x, code.pixel.y - pixel.y);
    if (best == nullptr || d < best_d) {
      best = &code;
      best_d = d;
    }
  }
  return best;
}

// The class a VLM takes a phrase for when the lexicon does not know it: the detector class it is
// a kind of (the offline backend's open-vocabulary table: "复印机" is a printer); "" when none.
std::string KnownClassOf(absl::string_view said) {
  const std::optional<modelproxy::offline::StandIn> stand_in =
      modelproxy::offline::OpenVocabularyStandIn(std::string(said));
  return stand_in.has_value() ? stand_in->known_class : "";
}

}  // namespace

std::string ChooseSearchAnswer(const FrameSighting& sighting, const std::vector<PrintedCode>& codes,
                               absl::string_view target, const SimVlmErrors& errors, Rng& rng,
                               double max_code_distance_px) {
  auto nameable = [&](const cv::Point2d& pixel) {
    const PrintedCode* code = Nearest(codes, pixel);
    return code == nullptr ||
           std::hypot(code->pixel.x - pixel.x, code->pixel.y - pixel.y) <= max_code_distance_px;
  };
  // A model reads the target as the operator wrote it: "汽车" is a car.
  const std::string canonical = CanonicalTerm(target);
  // Recognition: the target (unless missed) and anything taken for it; the largest nameable first.
  std::optional<cv::Point2d> clue;
  for (const FrameSighting::Instance& instance : sighting.instances) {
    const bool is_target =
        LabelNamesTarget(instance.label, target) || LabelNamesTarget(instance.label, canonical);
    const bool taken =
        is_target ? !rng.Bernoulli(errors.miss_rate) : rng.Bernoulli(errors.confusion_rate);
    if (taken && !clue.has_value() && nameable(instance.centroid)) clue = instance.centroid;
  }
  const bool hallucinated =
      !clue.has_value() && !codes.empty() && rng.Bernoulli(errors.hallucination_rate);
  if (hallucinated) clue = codes[rng.UniformInt(0, static_cast<int>(codes.size()) - 1)].pixel;
  std::string description;
  if (clue.has_value()) {
    description = absl::StrCat(target, " seen here");
  } else {  // evaluation: transfer through the largest nameable passage
    for (const FrameSighting::Passage& passage : sighting.passages) {
      if (!nameable(passage.centroid)) continue;
      clue = passage.centroid;
      description =
          absl::StrCat("no ", target, " here; ", passage.kind, " leading to another area");
      break;
    }
  }
  const bool off_by_one = rng.Bernoulli(errors.code_off_by_one_rate);
  if (!clue.has_value()) return kNothing;
  const PrintedCode* code = Nearest(codes, *clue);
  if (code == nullptr)
    return absl::StrCat("No position code is printed near the ", description, ".");
  return absl::StrCat("Code: ", off_by_one ? OffByOne(code->code, rng) : code->code,
                      ", Description: ", description);
}

bool LabelNamesTarget(absl::string_view label, absl::string_view target) {
  const std::string l = absl::AsciiStrToLower(label);
  const std::string t = absl::AsciiStrToLower(target);
  if (l.empty() || t.empty()) return false;
  if (l == t) return true;
  // Whole words: "red backpack" names "backpack"; "chair" does not name "armchair".
  auto contains_words = [](const std::string& haystack, const std::string& needle) {
    for (size_t at = haystack.find(needle); at != std::string::npos;
         at = haystack.find(needle, at + 1)) {
      const bool start = at == 0 || !std::isalnum(static_cast<unsigned char>(haystack[at - 1]));
      const size_t end = at + needle.size();
      const bool stop =
          end == haystack.size() || !std::isalnum(static_cast<unsigned char>(haystack[end]));
      if (start && stop) return true;
    }
    return false;
  };
  return contains_words(t, l) || contains_words(l, t);
}

absl::StatusOr<std::unique_ptr<SimVlm>> SimVlm::Create(const World& world, const FrameLog* frames,
                                                       SimVlmConfig config) {
  if (absl::Status s = ValidateSimVlmConfig(config); !s.ok()) return s;
  return std::unique_ptr<SimVlm>(new SimVlm(world, frames, std::move(config)));
}

SimVlm::SimVlm(const World& world, const FrameLog* frames, SimVlmConfig config)
    : world_(world), scene_(Scene::Build(world_)), frames_(frames), config_(std::move(config)) {}

SimVlm::TextEmbedding SimVlm::EmbedText(absl::string_view text) const {
  std::string said = CanonicalTerm(text);
  if (const std::string known = KnownClassOf(said); !known.empty()) said = known;
  // The classes the detector reports in this world: object labels and obstacle kinds (stuff).
  std::vector<std::string> classes;
  for (const ObjectInstance& object : world_.objects) classes.push_back(object.label);
  for (const Obstacle& obstacle : world_.obstacles) classes.push_back(obstacle.kind);
  TextEmbedding out;
  out.concept_name = said;
  bool exact = false;
  for (const std::string& label : classes) {
    const std::string canonical = CanonicalTerm(label);
    if (exact || !LabelNamesTarget(canonical, said)) continue;
    exact = canonical == said;
    // The exact class, else the most specific one the text names ("red cup" names "cup").
    if (exact || out.concept_name == said || label.size() > out.concept_name.size())
      out.concept_name = label;
  }
  Rng rng(MixSeed(config_.seed ^ 0x7e47, HashString(std::string(text))));
  out.vector = NoisyEmbedding(
      ClassEmbedding(out.concept_name, config_.embedding_dim, config_.embedding_seed),
      config_.text_embedding_noise, rng);
  out.latency_s = DrawLatency(rng, config_.latency.embedding_median_s, config_.latency);
  return out;
}

FrameSighting SimVlm::Sight(const RecordedFrame& frame) const {
  const RenderedView view =
      RenderView(scene_, frame.intrinsics, frame.world_from_camera, 0.1, config_.max_range_m);
  struct Sum {
    int pixels = 0;
    double u = 0, v = 0;
  };
  std::map<int, Sum> objects;
  std::map<std::string, Sum> kinds;
  const int width = frame.intrinsics.width;
  for (size_t p = 0; p < view.PixelCount(); ++p) {
    const int32_t surface = view.surface[p];
    if (surface < 0 || surface >= static_cast<int32_t>(scene_.solids().size())) continue;
    const SceneSolid& solid = scene_.solids()[surface];
    Sum* sum = solid.object_index >= 0 ? &objects[solid.object_index] : nullptr;
    if (sum == nullptr && std::find(config_.passage_kinds.begin(), config_.passage_kinds.end(),
                                    solid.kind) != config_.passage_kinds.end()) {
      sum = &kinds[solid.kind];
    }
    if (sum == nullptr) continue;
    ++sum->pixels;
    sum->u += static_cast<double>(p % width);
    sum->v += static_cast<double>(p / width);
  }
  FrameSighting sighting;
  for (const auto& [index, sum] : objects) {
    if (sum.pixels < config_.min_pixels) continue;
    sighting.instances.push_back({index, world_.objects[index].label, sum.pixels,
                                  cv::Point2d(sum.u / sum.pixels, sum.v / sum.pixels)});
  }
  for (const auto& [kind, sum] : kinds) {
    if (sum.pixels < config_.min_pixels) continue;
    sighting.passages.push_back(
        {kind, sum.pixels, cv::Point2d(sum.u / sum.pixels, sum.v / sum.pixels)});
  }
  std::stable_sort(sighting.instances.begin(), sighting.instances.end(),
                   [](const auto& a, const auto& b) { return a.pixels > b.pixels; });
  std::stable_sort(sighting.passages.begin(), sighting.passages.end(),
                   [](const auto& a, const auto& b) { return a.pixels > b.pixels; });
  return sighting;
}

absl::StatusOr<std::string> SimVlm::AnswerSearch(absl::string_view target, const cv::Mat& image,
                                                 uint64_t* frame_key) const {
  const std::optional<RecordedFrame> frame = frames_->Match(image, config_.max_changed_share);
  if (!frame.has_value())
    return std::string(kNothing);  // not a frame this camera took: nothing to see
  *frame_key = frame->index;
  const std::vector<PrintedCode> codes =
      ReadPrintedCodes(image, frame->image, config_.font_scale, config_.font_thickness);
  Rng rng(MixSeed(MixSeed(config_.seed, HashString(std::string(target))), frame->index));
  return ChooseSearchAnswer(Sight(*frame), codes, target, config_.errors, rng,
                            config_.max_code_distance_px);
}

std::string SimVlm::AnswerRegionScore(absl::string_view target,
                                      const std::vector<std::string>& descriptions) const {
  int naming = 0;
  const std::string seen = absl::StrCat(target, " seen");
  for (const std::string& description : descriptions)
    naming += description.find(seen) != std::string::npos;
  const int score = naming == 0 ? -2 : std::min(5, 1 + 2 * naming);
  return absl::StrCat(score);
}

absl::StatusOr<std::string> SimVlm::AnswerMatchTarget(absl::string_view task_json,
                                                      uint64_t* content_key) const {
  const nlohmann::json task = nlohmann::json::parse(task_json, nullptr, false);
  if (!task.is_object() || !task.contains("candidates") || !task["candidates"].is_array() ||
      !task.value("target", nlohmann::json()).is_string()) {
    return absl::InvalidArgumentError("match_target: needs target and candidates");
  }
  const std::string target = task["target"].get<std::string>();
  const std::string known_class = KnownClassOf(target);  // "复印机": a printer
  std::string content = target;
  nlohmann::json ranking = nlohmann::json::array();
  std::string best;
  std::vector<std::string> others;
  for (const nlohmann::json& candidate : task["candidates"]) {
    // json::value throws on a field of another type: checked here, before anything reads one.
    const auto text_or_absent = [&](const char* field) {
      return !candidate.contains(field) || candidate[field].is_string();
    };
    if (!candidate.is_object() || !text_or_absent("id") || !text_or_absent("label") ||
        !text_or_absent("description")) {
      return absl::InvalidArgumentError(
          "match_target: each candidate is an object whose id, label and description are strings");
    }
    const std::string id = candidate.value("id", "");
    const std::string label = candidate.value("label", "");
    absl::StrAppend(&content, "\n", label, "\t", candidate.value("description", ""));
    const bool match = LabelNamesTarget(label, target) ||
                       (!known_class.empty() && LabelNamesTarget(label, known_class));
    if (match && best.empty()) best = id;
    if (!match) others.push_back(id);
    ranking.push_back({{"id", id},
                       {"score", match ? 0.9 : 0.05},
                       {"reason", match ? "the label names the target" : "another class"}});
  }
  *content_key = HashString(content);
  Rng rng(MixSeed(config_.seed, *content_key));
  double confidence = best.empty() ? 0.0 : 0.85;
  if (!others.empty() && rng.Bernoulli(config_.errors.confusion_rate)) {  // label confusion
    best = others[rng.UniformInt(0, static_cast<int>(others.size()) - 1)];
    confidence = 0.7;
  }
  return nlohmann::json{{"best_id", best}, {"confidence", confidence}, {"ranking", ranking}}.dump();
}

absl::StatusOr<VlmReply> SimVlm::Answer(const VlmQuestion& question) const {
  VlmReply reply;
  uint64_t frame_key = 0;
  uint64_t text_key = HashString(question.text);
  const bool vision = !question.images.empty();
  if (const size_t at = question.text.rfind("{\"candidates\"");
      at != std::string::npos && question.text.find("match_target", at) != std::string::npos) {
    const size_t end = question.text.find('\n', at);
    absl::StatusOr<std::string> answer =
        AnswerMatchTarget(absl::string_view(question.text)
                              .substr(at, end == std::string::npos ? std::string::npos : end - at),
                          &text_key);
    if (!answer.ok()) return answer.status();
    reply.text = *std::move(answer);
  } else if (question.text.find("Output the code") != std::string::npos) {
    if (!vision) return absl::InvalidArgumentError("the search prompt needs an image");
    const std::string target = Between(question.text, "Target = [", "]");
    if (target.empty()) return absl::InvalidArgumentError("search prompt: no target");
    absl::StatusOr<std::string> answer = AnswerSearch(target, question.images.front(), &frame_key);
    if (!answer.ok()) return answer.status();
    reply.text = *std::move(answer);
  } else if (question.text.find("How likely is the [") != std::string::npos) {
    const std::string target = Between(question.text, "searching for [", "]");
    std::vector<std::string> descriptions;
    for (absl::string_view line : absl::StrSplit(question.text, '\n')) {
      if (absl::StartsWith(line, "- ")) descriptions.emplace_back(line.substr(2));
    }
    reply.text = AnswerRegionScore(target, descriptions);
  } else {
    return absl::InvalidArgumentError(
        "the simulated model answers the search, region-score and match_target prompts");
  }
  Rng rng(MixSeed(MixSeed(config_.seed ^ 0x5ca1ab1e, text_key), frame_key));
  const SimVlmLatency& l = config_.latency;
  reply.latency_s = DrawLatency(rng, vision ? l.vision_median_s : l.text_median_s, l);
  reply.input_tokens = vision ? config_.vision_input_tokens : config_.text_input_tokens;
  reply.output_tokens = 1 + static_cast<int>(reply.text.size() / 4);
  return reply;
}

}  // namespace semnav::sim::vlm

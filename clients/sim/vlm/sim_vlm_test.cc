#include "clients/sim/vlm/sim_vlm.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "clients/sim/core/class_embedding.h"
#include "clients/sim/core/detector.h"
#include "clients/sim/vlm/code_reader.h"
#include "clients/sim/vlm/sim_vlm_test_world.h"
#include "nlohmann/json.hpp"
#include "services/common/status/field_error.h"
#include "services/reasoning/core/search_prompts.h"
#include "services/reasoning/core/vlm_answer.h"

namespace semnav::sim::vlm {
namespace {

using testing::Capture;
using testing::GatewayEroi;
using testing::Pinhole;
using testing::SearchWorld;

const Eigen::Vector3d kCamera(0, 0, 1.5);

SimVlmConfig Perfect() {
  SimVlmConfig config;
  config.errors = SimVlmErrors{0, 0, 0, 0};
  return config;
}

// The gateway's side: codes printed into the frame, the search prompt with it.
struct Asked {
  VlmQuestion question;
  std::vector<reasoning::CodeLabel> labels;
};

Asked AskAbout(const SensorFrame& frame, double yaw, const std::string& target) {
  absl::StatusOr<reasoning::EroiSearch> search =
      reasoning::EroiSearch::Create(target, GatewayEroi());
  EXPECT_TRUE(search.ok()) << search.status();
  cv::Mat image = frame.rgb->clone();
  const reasoning::EroiObservation observation =
      search->Annotate(kCamera, testing::BodyOrientation(yaw), Pinhole(), image);
  return {VlmQuestion{observation.prompt, {image}}, observation.labels};
}

bool CutByBorder(const cv::Rect& box) {
  return box.x <= 0 || box.y <= 0 || box.x + box.width >= 160 || box.y + box.height >= 120;
}

// The sweep's accuracy scale: the defaults are accuracy 0.85; the other rates scale with the miss
// rate, and accuracy 1 is an error-free model.
TEST(SimVlmConfigTest, ErrorsAtAccuracyScaleTheDefaults) {
  const SimVlmErrors defaults = ErrorsAtAccuracy(0.85);
  EXPECT_NEAR(defaults.miss_rate, 0.15, 1e-12);
  EXPECT_NEAR(defaults.confusion_rate, 0.03, 1e-12);
  EXPECT_NEAR(defaults.hallucination_rate, 0.05, 1e-12);
  EXPECT_NEAR(defaults.code_off_by_one_rate, 0.10, 1e-12);
  const SimVlmErrors half = ErrorsAtAccuracy(0.5);
  EXPECT_NEAR(half.miss_rate, 0.5, 1e-12);
  EXPECT_NEAR(half.confusion_rate, 0.1, 1e-12);
  EXPECT_NEAR(half.hallucination_rate, 0.5 / 3, 1e-12);
  EXPECT_NEAR(half.code_off_by_one_rate, 1.0 / 3, 1e-12);
  const SimVlmErrors perfect = ErrorsAtAccuracy(1.0);
  EXPECT_EQ(perfect.miss_rate + perfect.confusion_rate + perfect.hallucination_rate +
                perfect.code_off_by_one_rate,
            0.0);
  const SimVlmErrors blind = ErrorsAtAccuracy(0.0);  // scale 1 / 0.15
  EXPECT_NEAR(blind.miss_rate, 1.0, 1e-12);
  EXPECT_NEAR(blind.code_off_by_one_rate, 2.0 / 3, 1e-12);
  EXPECT_NEAR(ErrorsAtAccuracy(-3.0).miss_rate, 1.0, 1e-12);  // clamped into [0, 1]
}

// The text tower of the detector's embedding space: a text naming a class of the world (in any
// wording the lexicon knows) lands near the vector the detector's detections of it carry, far from
// every other class; a concept the world has no class for is near none of them.
TEST(SimVlmTest, TextEmbeddingLiesNearTheDetectorsVectorOfTheClassItNames) {
  const World world = SearchWorld();  // backpack, bench, road
  FrameLog log;
  auto model = SimVlm::Create(world, &log, SimVlmConfig());
  ASSERT_TRUE(model.ok());
  const DetectorConfig detector;  // the embedding space SimVlmConfig's defaults name
  const std::vector<float> backpack =
      ClassEmbedding("backpack", detector.embedding_dim, detector.embedding_seed);
  const std::vector<float> bench =
      ClassEmbedding("bench", detector.embedding_dim, detector.embedding_seed);
  Rng rng(5);
  const std::vector<float> detection =
      NoisyEmbedding(backpack, detector.embedding_noise, rng);  // what one detection carries
  for (const std::string text : {"backpack", "the red backpack", "rucksacks", "背包"}) {
    const SimVlm::TextEmbedding embedded = (*model)->EmbedText(text);
    EXPECT_EQ(embedded.concept_name, "backpack") << text;
    ASSERT_EQ(embedded.vector.size(), 64u);
    // Noise of norm 0.3 on each side: about 1 / sqrt(1.09) = 0.96 to the class, 0.92 to a
    // detection.
    EXPECT_GT(CosineSimilarity(embedded.vector, backpack), 0.9) << text;
    EXPECT_GT(CosineSimilarity(embedded.vector, detection), 0.8) << text;
    EXPECT_LT(std::abs(CosineSimilarity(embedded.vector, bench)), 0.45) << text;
  }
  EXPECT_EQ((*model)->EmbedText("road").concept_name, "road");  // stuff is a class too
  const SimVlm::TextEmbedding coffee = (*model)->EmbedText("coffee machine");
  EXPECT_EQ(coffee.concept_name, "coffee machine");
  EXPECT_LT(std::abs(CosineSimilarity(coffee.vector, backpack)), 0.45);
  EXPECT_LT(std::abs(CosineSimilarity(coffee.vector, bench)), 0.45);
  // A pure function of (config, text).
  EXPECT_EQ((*model)->EmbedText("backpack").vector, (*model)->EmbedText("backpack").vector);
  EXPECT_NE((*model)->EmbedText("backpack").vector, (*model)->EmbedText("背包").vector);
}

TEST(SimVlmCodeReaderTest, ReadsEveryCodeTheGatewayPrinted) {
  const World world = SearchWorld();
  const Scene scene = Scene::Build(world);
  const SensorFrame frame = Capture(scene, kCamera, 0.0, 1);
  const Asked asked = AskAbout(frame, 0.0, "backpack");
  std::set<std::string> printed;
  for (const reasoning::CodeLabel& label : asked.labels) {
    if (!CutByBorder(label.box)) printed.insert(label.code);
  }
  ASSERT_GE(printed.size(), 4u);  // enough labels for the check to mean something
  std::set<std::string> read;
  for (const PrintedCode& code : ReadPrintedCodes(asked.question.images[0], *frame.rgb, 0.5, 1))
    read.insert(code.code);
  EXPECT_EQ(read, printed);
}

TEST(SimVlmTest, TargetInViewIsNamedByThePrintedCodeNearestIt) {
  const World world = SearchWorld();
  FrameLog log;
  const SensorFrame frame = Capture(Scene::Build(world), kCamera, 0.0, 7);
  log.Record(frame);
  auto model = SimVlm::Create(world, &log, Perfect());
  ASSERT_TRUE(model.ok()) << model.status();
  const Asked asked = AskAbout(frame, 0.0, "red backpack");
  absl::StatusOr<VlmReply> reply = (*model)->Answer(asked.question);
  ASSERT_TRUE(reply.ok()) << reply.status();
  const std::vector<reasoning::CodeDescription> pairs =
      reasoning::ParseCodeDescriptions(reply->text);
  ASSERT_EQ(pairs.size(), 1u) << reply->text;
  EXPECT_EQ(pairs[0].description, "red backpack seen here");
  // The named code is printed in the frame, and its EROI centre is near the backpack at (8, 0).
  auto printed =
      std::find_if(asked.labels.begin(), asked.labels.end(),
                   [&](const reasoning::CodeLabel& l) { return l.code == pairs[0].code; });
  ASSERT_NE(printed, asked.labels.end()) << pairs[0].code;
  EXPECT_LT((printed->world.head<2>() - Eigen::Vector2d(8, 0)).norm(), 4.5) << pairs[0].code;
  EXPECT_GT(reply->latency_s, 0.0);
  EXPECT_EQ(reply->input_tokens, 1083);
}

TEST(SimVlmTest, SameTargetOutOfViewGetsNoClue) {
  for (const bool wall : {false, true}) {
    const World world = SearchWorld(wall);
    const Scene scene = Scene::Build(world);
    FrameLog log;
    auto model = SimVlm::Create(world, &log, Perfect());
    ASSERT_TRUE(model.ok());
    // Facing away (yaw pi) or facing it behind a wall: no "seen here".
    for (const double yaw : wall ? std::vector<double>{0.0} : std::vector<double>{M_PI, M_PI / 2}) {
      const SensorFrame frame = Capture(scene, kCamera, yaw, log.size() + 1);
      log.Record(frame);
      absl::StatusOr<VlmReply> reply = (*model)->Answer(AskAbout(frame, yaw, "backpack").question);
      ASSERT_TRUE(reply.ok()) << reply.status();
      EXPECT_FALSE(absl::StrContains(reply->text, "seen here"))
          << "wall " << wall << " yaw " << yaw << ": " << reply->text;
    }
  }
}

TEST(SimVlmTest, WithoutAClueThePassageInViewIsNamed) {
  const World world = SearchWorld();
  const Scene scene = Scene::Build(world);
  FrameLog log;
  const double yaw = -M_PI / 2;  // facing the road at y = -6, away from backpack and bench
  const SensorFrame frame = Capture(scene, kCamera, yaw, 3);
  log.Record(frame);
  auto model = SimVlm::Create(world, &log, Perfect());
  ASSERT_TRUE(model.ok());
  absl::StatusOr<VlmReply> reply = (*model)->Answer(AskAbout(frame, yaw, "backpack").question);
  ASSERT_TRUE(reply.ok()) << reply.status();
  EXPECT_TRUE(absl::StrContains(reply->text, "road leading to another area")) << reply->text;
}

TEST(SimVlmTest, AnImageTheCameraNeverTookShowsNothing) {
  const World world = SearchWorld();
  FrameLog log;  // empty
  auto model = SimVlm::Create(world, &log, Perfect());
  ASSERT_TRUE(model.ok());
  const SensorFrame frame = Capture(Scene::Build(world), kCamera, 0.0, 1);
  absl::StatusOr<VlmReply> reply = (*model)->Answer(AskAbout(frame, 0.0, "backpack").question);
  ASSERT_TRUE(reply.ok());
  EXPECT_TRUE(reasoning::ParseCodeDescriptions(reply->text).empty()) << reply->text;
}

// Regression (issue 15): the search prompt carries the target as the operator wrote it, and the
// model compared that text with the labels in view, so "find 汽车" never saw a car (3 of the 15
// outdoor episodes, 汽车 and 桥, searched blind). A model reads Chinese: "汽车" is a car.
TEST(SimVlmTest, ATargetInChineseIsRecognised) {
  const SimVlmErrors none{0, 0, 0, 0};
  FrameSighting car;
  car.instances.push_back({0, "car", 100, cv::Point2d(40, 60)});
  const std::vector<PrintedCode> codes = {{"C5A", {}, {40, 60}}, {"D5A", {}, {90, 60}}};
  Rng rng(3);
  EXPECT_EQ(ChooseSearchAnswer(car, codes, "汽车", none, rng),
            "Code: C5A, Description: 汽车 seen here");
  EXPECT_EQ(ChooseSearchAnswer(car, codes, "长椅", none, rng), "No clue or passage.");  // a bench
}

// --- The error model: each rate measured over 4000 draws (binomial sd <= 0.008; bounds +-0.03).

FrameSighting Seen(std::vector<std::string> labels) {
  FrameSighting sighting;
  for (size_t i = 0; i < labels.size(); ++i) {
    sighting.instances.push_back(
        {static_cast<int>(i), labels[i], 100, cv::Point2d(40.0 + 50 * i, 60)});
  }
  return sighting;
}

const std::vector<PrintedCode> kCodes = {
    {"C5A", {}, {40, 60}}, {"D5A", {}, {90, 60}}, {"E7A", {}, {140, 100}}};

double Share(const FrameSighting& sighting, const SimVlmErrors& errors,
             const std::function<bool(const std::string&)>& counted) {
  constexpr int kDraws = 4000;
  int hits = 0;
  for (int i = 0; i < kDraws; ++i) {
    Rng rng(MixSeed(42, i));
    hits += counted(ChooseSearchAnswer(sighting, kCodes, "backpack", errors, rng));
  }
  return static_cast<double>(hits) / kDraws;
}

TEST(SimVlmErrorModelTest, MissRate) {
  SimVlmErrors errors{0.2, 0, 0, 0};
  const double missed = Share(Seen({"backpack"}), errors, [](const std::string& a) {
    return !absl::StrContains(a, "seen here");
  });
  EXPECT_NEAR(missed, 0.2, 0.03);
  errors.miss_rate = 0.0;
  EXPECT_EQ(
      Share(Seen({"backpack"}), errors,
            [](const std::string& a) { return a == "Code: C5A, Description: backpack seen here"; }),
      1.0);
}

TEST(SimVlmErrorModelTest, ConfusionRate) {
  const SimVlmErrors errors{0, 0.1, 0, 0};
  // One bench and nothing else: it is taken for the backpack (named by its code D5A? no: C5A, its
  // own pixel).
  const double confused = Share(Seen({"bench"}), errors, [](const std::string& a) {
    return a == "Code: C5A, Description: backpack seen here";
  });
  EXPECT_NEAR(confused, 0.1, 0.03);
}

TEST(SimVlmErrorModelTest, HallucinationRate) {
  const SimVlmErrors errors{0, 0, 0.05, 0};
  const double invented = Share(FrameSighting{}, errors, [](const std::string& a) {
    return absl::StrContains(a, "seen here");
  });
  EXPECT_NEAR(invented, 0.05, 0.03);
  EXPECT_GT(invented, 0.0);
  // Never when the target is truly there: hallucinations stand in only for a missing clue.
  const SimVlmErrors always{0, 0, 1.0, 0};
  EXPECT_EQ(Share(Seen({"backpack"}), always,
                  [](const std::string& a) { return absl::StrContains(a, "C5A"); }),
            1.0);
}

TEST(SimVlmErrorModelTest, CodeOffByOneCell) {
  const SimVlmErrors errors{0, 0, 0, 0.1};
  const std::set<std::string> neighbours = {"B5A", "D5A", "C4A", "C6A"};
  int off = 0, elsewhere = 0;
  for (int i = 0; i < 4000; ++i) {
    Rng rng(MixSeed(7, i));
    const std::vector<reasoning::CodeDescription> pairs = reasoning::ParseCodeDescriptions(
        ChooseSearchAnswer(Seen({"backpack"}), kCodes, "backpack", errors, rng));
    ASSERT_EQ(pairs.size(), 1u);
    off += neighbours.count(pairs[0].code);
    elsewhere += pairs[0].code != "C5A" && !neighbours.count(pairs[0].code);
  }
  EXPECT_NEAR(off / 4000.0, 0.1, 0.03);
  EXPECT_EQ(elsewhere, 0);
}

TEST(SimVlmErrorModelTest, AClueFarFromEveryPrintedCodeIsNotNamed) {
  const SimVlmErrors errors{0, 0, 0, 0};
  FrameSighting far = Seen({"backpack"});
  far.instances[0].centroid = cv::Point2d(40, 5);  // 55 px above C5A, the nearest code
  Rng rng(1);
  EXPECT_EQ(ChooseSearchAnswer(far, kCodes, "backpack", errors, rng, 40.0), "No clue or passage.");
  far.instances[0].centroid = cv::Point2d(40, 30);  // 30 px away: named
  EXPECT_EQ(ChooseSearchAnswer(far, kCodes, "backpack", errors, rng, 40.0),
            "Code: C5A, Description: backpack seen here");
}

TEST(SimVlmErrorModelTest, LatencyIsLogNormalAroundTheConfiguredMedian) {
  const World world = SearchWorld();
  FrameLog log;
  SimVlmConfig config = Perfect();
  config.latency.text_median_s = 0.35;
  config.latency.sigma = 0.4;
  config.latency.max_s = 1.0;
  auto model = SimVlm::Create(world, &log, config);
  ASSERT_TRUE(model.ok());
  std::vector<double> latencies;
  for (int i = 0; i < 2000; ++i) {
    const std::string prompt =
        reasoning::BuildRegionScorePrompt("backpack", {absl::StrCat("place ", i)});
    absl::StatusOr<VlmReply> reply = (*model)->Answer({prompt, {}});
    ASSERT_TRUE(reply.ok());
    latencies.push_back(reply->latency_s);
  }
  std::sort(latencies.begin(), latencies.end());
  EXPECT_NEAR(latencies[1000], 0.35, 0.02);  // the median
  // P(X > 1.0) for log-normal(ln 0.35, 0.4) is 0.44 %: a capped tail, never above the cap.
  EXPECT_LE(latencies.back(), 1.0);
  EXPECT_NEAR(latencies[1680] / latencies[1000], std::exp(0.4),
              0.08);  // the 84th percentile is median * e^sigma
}

TEST(SimVlmErrorModelTest, AnswersAreAFunctionOfTheSeed) {
  SimVlmErrors errors{0.5, 0.5, 0.5, 0.5};
  std::vector<std::string> first, again, other;
  for (int i = 0; i < 50; ++i) {
    Rng a(MixSeed(1, i)), b(MixSeed(1, i)), c(MixSeed(2, i));
    first.push_back(ChooseSearchAnswer(Seen({"backpack", "bench"}), kCodes, "backpack", errors, a));
    again.push_back(ChooseSearchAnswer(Seen({"backpack", "bench"}), kCodes, "backpack", errors, b));
    other.push_back(ChooseSearchAnswer(Seen({"backpack", "bench"}), kCodes, "backpack", errors, c));
  }
  EXPECT_EQ(first, again);
  EXPECT_NE(first, other);
}

TEST(SimVlmTest, RegionScoreAndMatchTarget) {
  const World world = SearchWorld();
  FrameLog log;
  auto model = SimVlm::Create(world, &log, Perfect());
  ASSERT_TRUE(model.ok());
  auto score = [&](std::vector<std::string> descriptions) {
    absl::StatusOr<VlmReply> reply =
        (*model)->Answer({reasoning::BuildRegionScorePrompt("backpack", descriptions), {}});
    EXPECT_TRUE(reply.ok());
    return reasoning::ParseRegionScore(reply->text);
  };
  EXPECT_EQ(*score({"backpack seen here", "no backpack here; road leading to another area"}), 3);
  EXPECT_EQ(*score({"backpack seen here", "backpack seen here", "backpack seen here"}), 5);
  EXPECT_EQ(*score({"no backpack here; road leading to another area"}), -2);
  const std::string task =
      R"({"candidates":[{"id":"4","label":"bench"},{"id":"9","label":"backpack"}],"target":"red backpack","task":"match_target"})";
  absl::StatusOr<VlmReply> match =
      (*model)->Answer({absl::StrCat("You help a robot find objects.\n", task), {}});
  ASSERT_TRUE(match.ok()) << match.status();
  EXPECT_TRUE(absl::StrContains(match->text, R"("best_id":"9")")) << match->text;
  EXPECT_EQ((*model)->Answer({"tell me a joke", {}}).status().code(),
            absl::StatusCode::kInvalidArgument);
  for (const char* bad_candidates :
       {R"([{"id":4,"label":"bench"}])", R"([{"id":"4","label":["bench"]}])",
        R"([{"id":"4","label":"bench","description":7}])", R"(["bench"])"}) {
    const std::string bad = absl::StrCat(R"({"candidates":)", bad_candidates,
                                         R"(,"target":"backpack","task":"match_target"})");
    EXPECT_EQ((*model)->Answer({absl::StrCat("Find it.\n", bad), {}}).status().code(),
              absl::StatusCode::kInvalidArgument)
        << bad;
  }
}

// Mapping numbers objects over the service's life, so the ids a question names depend on the
// episodes mapped before it on the same stack: the answer and its latency must not.
TEST(SimVlmTest, MatchTargetAnswerAndLatencyDoNotDependOnTheCandidatesIds) {
  const World world = SearchWorld();
  FrameLog log;
  SimVlmConfig config;
  config.errors.confusion_rate = 0.5;  // so that the draws decide half of the answers
  auto model = SimVlm::Create(world, &log, config);
  ASSERT_TRUE(model.ok());
  auto ask = [&](int first_id, const std::string& target) {
    const std::string task =
        absl::StrCat(R"({"candidates":[{"id":")", first_id, R"(","label":"bench"},{"id":")",
                     first_id + 1, R"(","label":"backpack"},{"id":")", first_id + 2,
                     R"(","label":"road"}],"target":")", target, R"(","task":"match_target"})");
    absl::StatusOr<VlmReply> reply = (*model)->Answer({absl::StrCat("Find it.\n", task), {}});
    EXPECT_TRUE(reply.ok()) << reply.status();
    const nlohmann::json answer = nlohmann::json::parse(reply->text);
    const std::string best = answer["best_id"].get<std::string>();
    const int chosen = best.empty() ? -1 : std::stoi(best) - first_id;  // candidate index
    return std::make_pair(chosen, reply->latency_s);
  };
  int confused = 0;
  for (int i = 0; i < 40; ++i) {
    const std::string target = absl::StrCat("backpack number ", i);
    const auto fresh = ask(1, target);
    EXPECT_EQ(ask(57, target), fresh) << target;  // the same episode after 56 earlier objects
    confused += fresh.first != 1;
  }
  EXPECT_GT(confused, 5);  // the draws did decide answers
  EXPECT_LT(confused, 35);
}

TEST(SimVlmErrorModelTest, TextEncoderLatencyIsDrawnPerTextAroundItsMedian) {
  const World world = SearchWorld();
  FrameLog log;
  SimVlmConfig config;
  config.latency.embedding_median_s = 0.03;
  config.latency.sigma = 0.4;
  auto model = SimVlm::Create(world, &log, config);
  ASSERT_TRUE(model.ok());
  std::vector<double> latencies;
  for (int i = 0; i < 2000; ++i)
    latencies.push_back((*model)->EmbedText(absl::StrCat("thing ", i)).latency_s);
  std::sort(latencies.begin(), latencies.end());
  EXPECT_NEAR(latencies[1000], 0.03, 0.003);  // the median, in whole milliseconds
  EXPECT_GT(latencies.front(), 0.0);
  EXPECT_EQ((*model)->EmbedText("backpack").latency_s, (*model)->EmbedText("backpack").latency_s);
}

TEST(SimVlmTest, ConfigIsValidated) {
  const World world = SearchWorld();
  FrameLog log;
  SimVlmConfig config;
  config.errors.miss_rate = 1.5;
  const auto bad = SimVlm::Create(world, &log, config);
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(bad.status()), "errors.miss_rate");
  config = SimVlmConfig();
  config.latency.vision_median_s = -1;
  EXPECT_EQ(ErrorField(SimVlm::Create(world, &log, config).status()), "latency.vision_median_s");
  config = SimVlmConfig();
  config.latency.embedding_median_s = 0;
  EXPECT_EQ(ErrorField(SimVlm::Create(world, &log, config).status()), "latency.embedding_median_s");
  config = SimVlmConfig();
  config.embedding_dim = 0;
  EXPECT_EQ(ErrorField(SimVlm::Create(world, &log, config).status()), "embedding_dim");
  config = SimVlmConfig();
  config.text_embedding_noise = -0.1;
  EXPECT_EQ(ErrorField(SimVlm::Create(world, &log, config).status()), "text_embedding_noise");
}

TEST(SimVlmTest, LabelNamesTargetByWholeWords) {
  EXPECT_TRUE(LabelNamesTarget("backpack", "red backpack"));
  EXPECT_TRUE(LabelNamesTarget("potted plant", "Potted Plant"));
  EXPECT_FALSE(LabelNamesTarget("chair", "armchair"));
  EXPECT_FALSE(LabelNamesTarget("bench", "backpack"));
}

}  // namespace
}  // namespace semnav::sim::vlm

// results.json / results.csv / cache entries read back exactly; merge joins by key.
#include "sweep/results_io.h"

#include <gtest/gtest.h>

#include "runtime/images/atomic_file.h"
#include "support/test_support.h"
#include "sweep/merge.h"

namespace shadowc::sweep {
namespace {

Row sample(const std::string& key, size_t variant, double ms, double rmse) {
  Row r;
  r.key = key;
  r.variantIndex = variant;
  r.variant = "pcss[taps=" + std::to_string(variant) + "]";
  r.base = "pcss";
  r.params = {{"taps", std::to_string(variant)}};
  r.caseLabel = "two_planes 64px map 256";
  r.scene = "two_planes";
  r.sceneHash = "abc";
  r.screen = 64;
  r.map = 256;
  r.referenceSamples = 4;
  r.runs = 2;
  r.warmup = 1;
  r.spec = {{"name", "pcss"}, {"note", "a \"quoted\", comma"}};
  r.filterText = "filter pcss {\n    depth\n}\n";
  r.normalizedText = "filter pcss {\n    depth\n    bias constant(0.001)\n}\n";
  r.contentHash = "xxh3-128:00";
  r.passes = {{"shade", "shade", ms}};
  r.totalMs = ms;
  r.metrics.rmse = rmse;
  r.metrics.compared = r.metrics.pixels = 100;
  r.device = "llvmpipe";
  r.resultImage = "images/" + key + "-result.png";
  return r;
}

TEST(ResultsIo, JsonRoundTripAndCache) {
  Results res;
  res.sweep = "t";
  res.rows = {sample("k1", 1, 2.5, 0.1), sample("k2", 2, 1.25, 0.2)};
  res.rows[0].work = rt::WorkCounts{"shade", {"receivers", "depth_fetches", "moment_bounds"}, {100, 2500, 7}};
  res.skipped = {{3, "bad", "E0416", "bad:1:1: error: x [E0416]"}};
  res.stats = {2, 0};
  const Results back = parseResultsJson(resultsJson(res), "r.json");
  ASSERT_EQ(back.rows.size(), 2u);
  EXPECT_EQ(rowToJson(back.rows[0]).dump(), rowToJson(res.rows[0]).dump());
  ASSERT_TRUE(back.rows[0].work.has_value());  // the work counts come back field by field
  EXPECT_EQ(*back.rows[0].work, *res.rows[0].work);
  EXPECT_FALSE(back.rows[1].work.has_value());
  EXPECT_EQ(back.skipped[0].code, "E0416");
  const auto dir = test::freshTempDir("sweep-cache");
  EXPECT_FALSE(readCachedRow(dir, "k1"));
  writeCachedRow(dir, res.rows[0]);
  ASSERT_TRUE(readCachedRow(dir, "k1"));
  EXPECT_EQ(readCachedRow(dir, "k1")->totalMs, 2.5);
  rt::writeFileAtomically(cachePath(dir, "k2"), "{ truncated");  // a damaged entry is a miss
  EXPECT_FALSE(readCachedRow(dir, "k2"));
}

TEST(ResultsIo, CsvQuotesAndMarksTheFrontier) {
  Results res;
  res.rows = {sample("k1", 1, 2.5, 0.1), sample("k2", 2, 1.25, 0.2), sample("k3", 3, 3.0, 0.3)};
  const std::string csv = resultsCsv(res);
  EXPECT_NE(csv.find("\"{\"\"name\"\":\"\"pcss\"\",\"\"note\"\":\"\"a \\\"\"quoted\\\"\", comma\"\"}\""),
            std::string::npos)
      << csv;
  // k3 is slower and worse than both: frontier column 0; the others 1.
  EXPECT_NE(csv.find(",0,shade=3.0000,xxh3-128:00,k3,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",1,shade=2.5000,xxh3-128:00,k1,"), std::string::npos) << csv;
}

TEST(Merge, JoinsByKeyInJobOrder) {
  const auto a = test::freshTempDir("sweep-merge-a"), b = test::freshTempDir("sweep-merge-b"),
             out = test::freshTempDir("sweep-merge-out");
  Results ra, rb;
  ra.sweep = rb.sweep = "t";
  ra.rows = {sample("k2", 2, 1, 0.2)};
  rb.rows = {sample("k1", 1, 2, 0.1), sample("k2", 2, 9, 0.9)};  // k2 twice: the first folder's wins
  ra.skipped = rb.skipped = {{0, "bad", "E0416", "m"}};
  rt::writeFileAtomically(a / "results.json", resultsJson(ra));
  rt::writeFileAtomically(b / "results.json", resultsJson(rb));
  rt::writeFileAtomically(a / "images/k2-result.png", "png");
  const Results m = mergeResults({a, b}, out);
  ASSERT_EQ(m.rows.size(), 2u);
  EXPECT_EQ(m.rows[0].key, "k1");
  EXPECT_EQ(m.rows[1].totalMs, 1);
  EXPECT_EQ(m.skipped.size(), 1u);
  EXPECT_EQ(test::readFile(out / "images/k2-result.png"), "png");
  EXPECT_TRUE(readCachedRow(out, "k1"));  // the merged folder resumes too
  EXPECT_THROW(mergeResults({out / "nothing"}, out), std::runtime_error);
}

}  // namespace
}  // namespace shadowc::sweep

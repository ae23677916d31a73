#include "massprops/analysis/finding_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace massprops {
namespace {

// Expected strings worked out by hand: %.3g rounding, then the exponent written short.
TEST(FindingTextTest, NumbersHaveThreeSignificantDigitsAndShortExponents) {
  EXPECT_EQ(FormatSignificant(0.00903767), "0.00904");
  EXPECT_EQ(FormatSignificant(2), "2");
  EXPECT_EQ(FormatSignificant(-0.5), "-0.5");
  EXPECT_EQ(FormatSignificant(1234567), "1.23e6");
  EXPECT_EQ(FormatSignificant(1234), "1230");  // whole below 1e5
  EXPECT_EQ(FormatSignificant(99999), "1e5");  // %.3g rounds it to 1.00e5
  EXPECT_EQ(FormatSignificant(8.45427e-06), "8.45e-6");
  EXPECT_EQ(FormatSignificant(std::nan("")), "nan");
  EXPECT_EQ(FormatSignificant(-HUGE_VAL), "-inf");
}

TEST(FindingTextTest, LengthsBelowOneMetreAreInMillimetresOrCentimetres) {
  EXPECT_EQ(FormatLength(0.00903767), "9.04 mm");  // below 1 cm: ×1000
  EXPECT_EQ(FormatLength(0.15), "15 cm");          // below 1 m: ×100
  EXPECT_EQ(FormatLength(0.212132), "21.2 cm");
  EXPECT_EQ(FormatLength(2.5), "2.5 m");
  EXPECT_EQ(FormatLength(0.99996), "1 m");  // rounds to 1.00 m, not "100 cm"
  EXPECT_EQ(FormatLength(0), "0 mm");
}

TEST(FindingTextTest, RatiosAreWrittenWithAnX) {
  EXPECT_EQ(FormatRatio(577.3), "577x");
  EXPECT_EQ(FormatRatio(1e6), "1e6x");
  EXPECT_EQ(FormatRatio(0.0180021), "0.018x");
}

TEST(FindingTextTest, BoxExtentsShareTheUnitOfTheLargest) {
  EXPECT_EQ(FormatExtents(0.04, 0.04, 0.1), "4 × 4 × 10 cm");
  EXPECT_EQ(FormatExtents(0.5, 0.2, 1.2), "0.5 × 0.2 × 1.2 m");
}

TEST(FindingTextTest, EvidenceIsRenderedByTheUnitItsNameEndsIn) {
  EXPECT_EQ(FormatEvidenceValue("mass_kg", 2), "2 kg");
  EXPECT_EQ(FormatEvidenceValue("half_diagonal_m", 0.212132), "21.2 cm");
  EXPECT_EQ(FormatEvidenceValue("trace_kg_m2", 0.0279167), "0.0279 kg·m²");
  EXPECT_EQ(FormatEvidenceValue("density_kg_m3", 45.2), "45.2 kg/m³");
  EXPECT_EQ(FormatEvidenceValue("ratio", 577.3), "577x");
  EXPECT_EQ(FormatEvidenceValue("k_over_e_ratio", 0.018), "0.018x");
  EXPECT_EQ(FormatEvidenceValue("links_count", 29), "29");
  EXPECT_EQ(FormatEvidenceValue("group_share_percent", 8.1234), "8.12%");
  EXPECT_EQ(FormatEvidenceValue("cosine", -0.98765), "-0.988");
  EXPECT_EQ(EvidenceLabel("half_diagonal_m"), "half diagonal");
  EXPECT_EQ(EvidenceLabel("k_over_e_ratio"), "k/e");
  EXPECT_EQ(EvidenceLabel("principal_min_kg_m2"), "principal min");
  EXPECT_EQ(EvidenceLabel("ratio"), "ratio");
}

TEST(FindingTextTest, EvidenceLineKeepsWhatFitsAndMarksTheRest) {
  const std::vector<std::pair<std::string, double>> evidence = {
      {"k_m", 8.7}, {"half_diagonal_m", 0.15}, {"ratio", 58}, {"mass_kg", 2}};
  EXPECT_EQ(FormatEvidence(evidence), "k 8.7 m, half diagonal 15 cm, ratio 58x, mass 2 kg");
  // 30 characters: "k 8.7 m" (7) + ", half diagonal 15 cm" (21) = 28, and 3 more for ", …" do
  // not fit: the second item is left out.
  EXPECT_EQ(FormatEvidence(evidence, 30), "k 8.7 m, …");
  EXPECT_EQ(FormatEvidence({}), "");
}

TEST(FindingTextTest, HeadlineFallsBackToTheMessage) {
  Finding f;
  f.message = "the whole sentence";
  EXPECT_EQ(HeadlineOf(f), "the whole sentence");
  f.headline = "short";
  EXPECT_EQ(HeadlineOf(f), "short");
}

TEST(FindingTextTest, EveryRuleHasALongFormFromDocsRulesMd) {
  for (const RuleInfo& rule : AllRules()) {
    const std::optional<std::string> text = RuleLongForm(rule.id);
    ASSERT_TRUE(text.has_value()) << rule.id;
    // The section starts with its own heading (### or ####).
    EXPECT_NE(text->find("# `" + std::string(rule.id) + "`"), std::string::npos) << rule.id;
  }
  EXPECT_FALSE(RuleLongForm("no-such-rule").has_value());
  EXPECT_EQ(RulesWithLongForm().front(), "mass-not-positive");  // the first section of the page
}

}  // namespace
}  // namespace massprops

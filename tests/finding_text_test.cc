#include "massprops/analysis/finding_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "massprops/analysis/fix_text.h"

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
  EXPECT_EQ(FormatEvidenceValue("gyration_to_half_diagonal_ratio", 0.018), "0.018x");
  EXPECT_EQ(FormatEvidenceValue("links_count", 29), "29");
  EXPECT_EQ(FormatEvidenceValue("share_of_welded_group_percent", 8.1234), "8.12%");
  EXPECT_EQ(FormatEvidenceValue("cosine", -0.98765), "-0.988");
  EXPECT_EQ(EvidenceLabel("half_diagonal_m"), "half diagonal");
  EXPECT_EQ(EvidenceLabel("radius_of_gyration_m"), "radius of gyration");
  EXPECT_EQ(EvidenceLabel("smallest_moment_kg_m2"), "smallest moment");
  EXPECT_EQ(EvidenceLabel("ratio"), "ratio");
  // The center of mass as robot engineers write it; "com" inside a word is left alone.
  EXPECT_EQ(EvidenceLabel("com_x_m"), "COM x");
  EXPECT_EQ(EvidenceLabel("com_off_mirror_image_m"), "COM off mirror image");
  EXPECT_EQ(EvidenceLabel("composite_mass_kg"), "composite mass");
}

TEST(FindingTextTest, EvidenceGoesOnAsManyWholeLinesAsItNeeds) {
  const std::vector<std::pair<std::string, double>> evidence = {
      {"radius_of_gyration_m", 8.7}, {"half_diagonal_m", 0.15}, {"ratio", 58}, {"mass_kg", 2}};
  EXPECT_EQ(FormatEvidence(evidence),
            "radius of gyration 8.7 m, half diagonal 15 cm, ratio 58x, mass 2 kg");
  // Counted by hand: "radius of gyration 8.7 m" (24) + ", half diagonal 15 cm" (21) = 45 fit
  // in 45; ", ratio 58x" would make 56: the third item starts a second line, and ", mass 2 kg"
  // (11) fits beside it. Nothing is left out, nothing cut.
  EXPECT_EQ(FormatEvidenceLines(evidence, 45),
            (std::vector<std::string>{"radius of gyration 8.7 m, half diagonal 15 cm",
                                      "ratio 58x, mass 2 kg"}));
  EXPECT_EQ(FormatEvidence(evidence, 45),
            "radius of gyration 8.7 m, half diagonal 15 cm\nratio 58x, mass 2 kg");
  EXPECT_EQ(FormatEvidenceLines(evidence).size(), 1u);
  EXPECT_EQ(FormatEvidence({}), "");
  EXPECT_TRUE(FormatEvidenceLines({}).empty());
}

TEST(FindingTextTest, ListsAreJoinedIntoWholeLinesCountedInCharacters) {
  // "a, bb" is 5 characters; ", cc" would make 9 > 6.
  EXPECT_EQ(JoinIntoLines({"a", "bb", "cc"}, 6), (std::vector<std::string>{"a, bb", "cc"}));
  // An item longer than the line stands alone, whole.
  EXPECT_EQ(JoinIntoLines({"a", "bbbbbbbb", "c"}, 6),
            (std::vector<std::string>{"a", "bbbbbbbb", "c"}));
  // "2 kg·m²" is 7 characters (9 bytes): "x, 2 kg·m²" is 10, which fits in 10.
  EXPECT_EQ(JoinIntoLines({"x", "2 kg·m²"}, 10), (std::vector<std::string>{"x, 2 kg·m²"}));
  EXPECT_TRUE(JoinIntoLines({}, 10).empty());
}

TEST(FindingTextTest, ProseIsWrappedAtSpacesWithoutCuttingAWord) {
  // "the mass" is 8; " is" would make 11 > 10.
  EXPECT_EQ(WrapWords("the mass is  zero here", 10),
            (std::vector<std::string>{"the mass", "is zero", "here"}));
  EXPECT_EQ(WrapWords("a verylongword b", 5), (std::vector<std::string>{"a", "verylongword", "b"}));
  EXPECT_EQ(WrapWords("kg·m² kg·m²", 11), (std::vector<std::string>{"kg·m² kg·m²"}));
  EXPECT_TRUE(WrapWords("  ", 10).empty());
}

TEST(FindingTextTest, HeadlineFallsBackToTheMessage) {
  Finding f;
  f.message = "the whole sentence";
  EXPECT_EQ(HeadlineOf(f), "the whole sentence");
  f.headline = "short";
  EXPECT_EQ(HeadlineOf(f), "short");
  EXPECT_EQ(HeadlineOf(Finding()), "");  // neither set: nothing to say
}

// Hand-counted: "link '" (6) + name + "'" (1) + after.
TEST(FindingTextTest, LinkHeadlineNamesTheLinkWhenTheSentenceFits) {
  const std::string after = ": mass -1 kg is negative; no body has it";  // 40 characters
  EXPECT_EQ(LinkHeadline("arm", after), "link 'arm': mass -1 kg is negative; no body has it");
  // A name of 63 characters: 6 + 63 + 1 + 40 = 110, the most a headline has: kept whole.
  const std::string name63(63, 'n');
  EXPECT_EQ(LinkHeadline(name63, after), "link '" + name63 + "'" + after);
  EXPECT_EQ(CountChars(LinkHeadline(name63, after)), 110u);
  // Text before the name: "MuJoCo 2.2.2 refuses " (21) + "link 'arm'" (10) + after.
  EXPECT_EQ(LinkHeadline("arm", ": negative mass", "MuJoCo 2.2.2 refuses "),
            "MuJoCo 2.2.2 refuses link 'arm': negative mass");
}

TEST(FindingTextTest, LinkHeadlineKeepsTheNameWithoutTheGuessedCauseBeforeSayingThisLink) {
  // pr2.urdf's camera frame (42 characters): 6 + 42 + 1 + 62 = 111, one too many; without the
  // cause guessed in parentheses (the help repeats it) 6 + 42 + 1 + 38 = 87 fits.
  const std::string name = "narrow_stereo_gazebo_l_stereo_camera_frame";
  const std::string after = ": inertia 8000x too large for its size (units or placeholder?)";
  ASSERT_EQ(CountChars(name), 42u);
  ASSERT_EQ(CountChars(after), 62u);
  EXPECT_EQ(LinkHeadline(name, after), "link '" + name + "': inertia 8000x too large for its size");
  // A name of 80 characters fits neither (6 + 80 + 1 + 38 = 125): "this link", cause kept.
  EXPECT_EQ(LinkHeadline(std::string(80, 'n'), after), "this link" + after);
}

TEST(FindingTextTest, LinkHeadlineSaysThisLinkWhenTheNameWouldNotFit) {
  const std::string after = ": mass -1 kg is negative; no body has it";
  // 64 characters: 111 with the name, one too many. The sentence is kept whole, about "this
  // link" (file:line and JSON's `link` name it): never a cut name, never "…".
  const std::string name64(64, 'n');
  EXPECT_EQ(LinkHeadline(name64, after), "this link: mass -1 kg is negative; no body has it");
  // An absurd name (10 000 characters, a generated one): the same short sentence.
  EXPECT_EQ(LinkHeadline(std::string(10000, 'x'), " has no <inertial>", "MuJoCo 2.2.2 refuses "),
            "MuJoCo 2.2.2 refuses this link has no <inertial>");
  // Multi-byte characters count once: 55 "é" (110 bytes) + 6 + 1 + 40 = 102 characters fit.
  std::string accented;
  for (int i = 0; i < 55; ++i) accented += "\xC3\xA9";
  EXPECT_EQ(LinkHeadline(accented, after), "link '" + accented + "'" + after);
  EXPECT_EQ(ModelHeadline(std::string(200, 'm'), ": all 3 links weigh 1000 kg/m³"),
            "this model: all 3 links weigh 1000 kg/m³");
}

TEST(FindingTextTest, LinkHeadlineFirstFitKeepsTheNameWithAShorterSentence) {
  const std::string longer =
      ": placeholder inertia copied onto 13 links, radius of gyration 4.3x "
      "the reach of its assembly";  // 93 characters
  const std::string shorter = ": placeholder inertia on 13 links, 4.3x too wide for its assembly";
  ASSERT_EQ(CountChars(longer), 93u);
  ASSERT_EQ(CountChars(shorter), 65u);
  // "link 'arm'" (10) + 93 = 103 fits.
  EXPECT_EQ(LinkHeadlineFirstFit("arm", {longer, shorter}), "link 'arm'" + longer);
  // A 33-character name: 6 + 33 + 1 + 93 = 133 does not; with the shorter, 105 does.
  const std::string name = "wide_stereo_l_stereo_camera_frame";
  EXPECT_EQ(LinkHeadlineFirstFit(name, {longer, shorter}), "link '" + name + "'" + shorter);
  // A 50-character name fits neither (6 + 50 + 1 + 65 = 122): "this link" with the shorter.
  EXPECT_EQ(LinkHeadlineFirstFit(std::string(50, 'n'), {longer, shorter}), "this link" + shorter);
}

TEST(FindingTextTest, LongestLeadThatFitsDropsTheMostSpecificDetailsFromTheEnd) {
  // As an unreadable STL is reported (assimp's reason here 66 characters long): the whole is
  // 84 + 2 + 66 = 152 characters; the lead up to the last ": " is 84.
  const std::string lead =
      "link 'a': mesh cannot be used: collision at line 7: mesh file 'g.stl' "
      "cannot be read";
  ASSERT_EQ(CountChars(lead), 84u);
  EXPECT_EQ(LongestLeadThatFits(lead + ": " + std::string(66, 'r')), lead);
  // Parenthetical remarks are left out first: "(mesh 'g.stl')" does not count.
  EXPECT_EQ(LongestLeadThatFits("link 'a': mesh cannot be used: collision at line 7 (mesh "
                                "'g.stl'): mesh file 'g.stl' cannot be read: " +
                                std::string(66, 'r')),
            lead);
  // No ": " within the first 110 characters: nothing.
  EXPECT_EQ(LongestLeadThatFits(std::string(120, 'w') + ": x"), "");
}

TEST(FindingTextTest, FirstThatFitsTakesTheFullestSentenceThatFits) {
  const std::string twin(80, 't');
  // "link 'arm'" (10) + ": center of mass 2 cm off the mirror image of " (46) + "link '" (6) +
  // 80 + "'" (1) = 143 characters: too long; the second (59) fits.
  EXPECT_EQ(
      FirstThatFits({"link 'arm': center of mass 2 cm off the mirror image of link '" + twin + "'",
                     "link 'arm': center of mass 2 cm off its twin's mirror image"}),
      "link 'arm': center of mass 2 cm off its twin's mirror image");
  EXPECT_EQ(FirstThatFits({"short", "shorter"}), "short");
  // None fits: the last, which its author keeps short.
  EXPECT_EQ(FirstThatFits({std::string(200, 'a'), std::string(120, 'b')}), std::string(120, 'b'));
}

TEST(FindingTextTest, HeadlineFromMessageKeepsWholeClausesNeverCutsOne) {
  // Short enough: the text itself.
  EXPECT_EQ(HeadlineFromMessage("<inertia>: ixx is not a number", "F"),
            "<inertia>: ixx is not a number");
  // 41 + 2 + 100 characters: too long; the first clause (before "; ") stands alone.
  const std::string first = "<inertia ixx=\"1,5\"> of link 'a' is unread";  // 41 characters
  EXPECT_EQ(CountChars(first), 41u);
  EXPECT_EQ(HeadlineFromMessage(first + "; " + std::string(100, 'w'), "F"), first);
  // The longest run of clauses that fits: 41 + 2 + 50 = 93 fits, + 2 + 50 more does not.
  const std::string second(50, 's');
  EXPECT_EQ(HeadlineFromMessage(first + "; " + second + "; " + std::string(50, 'x'), "F"),
            first + "; " + second);
  // Parenthetical remarks left out keep the sentence whole: tinyxml2's error (as on the corpus's
  // malformed files), 51 characters without its 130-character remark (181 with it).
  const std::string remark =
      " (Error=XML_ERROR ErrorID=11 (0xb) Line number=17: " + std::string(78, 'v') + ")";
  EXPECT_EQ(CountChars(remark), 130u);
  EXPECT_EQ(
      HeadlineFromMessage("<sdf>: malformed XML: XML_ERROR_PARSING_DECLARATION" + remark, "F"),
      "<sdf>: malformed XML: XML_ERROR_PARSING_DECLARATION");
  // No clause fits: the lead up to the first ": " (what the rest details), and `more`.
  EXPECT_EQ(HeadlineFromMessage("<mesh>: " + std::string(200, 'p'), "F", "more follows"),
            "<mesh>: more follows");
  EXPECT_EQ(HeadlineFromMessage("<joint> 'j': bad pose: " + std::string(200, 'p'), "F", "more"),
            "<joint> 'j': more");
  // Not even the lead fits (a 200-character element): the fallback alone.
  EXPECT_EQ(HeadlineFromMessage(std::string(200, 'e') + ": " + std::string(20, 'p'), "fallback"),
            "fallback");
  // HeadlineOf applies it to a message too long for a headline.
  Finding f;
  f.message = "link 'a': " + std::string(300, 'z');
  EXPECT_EQ(HeadlineOf(f), "link 'a': --explain gives the whole message");
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

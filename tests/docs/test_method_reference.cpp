// docs/methods.md's method reference is the text generated from the descriptors, so it cannot go
// stale; and this binary, like glintlab, lists only the built-in methods.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "scene/materials/material_reference.hpp"
#include "shading/method_reference.hpp"
#include "shading/registry.hpp"

using namespace glintlab;

namespace {

constexpr const char* kBegin = "<!-- generated:method-reference -->\n";
constexpr const char* kEnd = "<!-- /generated:method-reference -->\n";

/// "line N: docs `...` generated `...`" for the first line where the two texts differ.
std::string first_difference(const std::string& docs, const std::string& generated) {
  std::istringstream a(docs), b(generated);
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, la)), more_b = static_cast<bool>(std::getline(b, lb));
    if (!more_a && !more_b) return "none";
    if (more_a != more_b || la != lb)
      return "line " + std::to_string(line) + " of the block: docs `" + (more_a ? la : "(end)") + "`, generated `" +
             (more_b ? lb : "(end)") + "`";
  }
}

}  // namespace

TEST(MethodReference, DocsHoldTheReferenceGeneratedFromTheDescriptors) {
  std::ifstream in(GLINTLAB_SOURCE_DIR "/docs/methods.md", std::ios::binary);
  ASSERT_TRUE(in) << "cannot read docs/methods.md";
  std::stringstream s;
  s << in.rdbuf();
  const std::string docs = s.str();
  const auto begin = docs.find(kBegin);
  const auto end = docs.find(kEnd);
  ASSERT_NE(begin, std::string::npos) << "docs/methods.md lacks the line " << kBegin;
  ASSERT_NE(end, std::string::npos) << "docs/methods.md lacks the line " << kEnd;
  ASSERT_LT(begin, end);
  const std::string block = docs.substr(begin + std::string(kBegin).size(), end - begin - std::string(kBegin).size());
  const std::string generated = method_reference_markdown(all_methods());
  EXPECT_TRUE(block == generated) << "docs/methods.md's method reference differs from the descriptors ("
                                  << first_difference(block, generated) << "); regenerate it:\n"
                                  << "  tools/update-reference-docs.sh";
}

TEST(MethodReference, HasASectionAndATableRowPerParameter) {
  const std::string text = method_reference_markdown(all_methods());
  for (const auto& m : all_methods()) {
    EXPECT_NE(text.find("### `" + m.id + "`: " + m.title + "\n"), std::string::npos) << m.id;
    for (const auto& p : m.params) EXPECT_NE(text.find("| `" + p.name + "` | `"), std::string::npos) << p.name;
  }
  EXPECT_NE(text.find("| `area` | `exact` | `exact\\|circle\\|lens` |"), std::string::npos);  // '|' escaped
}

TEST(MethodReference, TheBinaryListsOnlyTheBuiltInMethods) {
  std::vector<std::string> ids;
  for (const auto& m : all_methods()) ids.push_back(m.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"conventional", "toksvig", "vlachos", "kaplanyan-beckmann", "kaplanyan-rect",
                                           "kaplanyan-ggx", "tokuyoshi", "lean", "podee", "chermain2020",
                                           "chermain2021", "deliot2023", "kneiphof2024", "kneiphof2025", "yan2016", "deng2022",
                                           "kemppinen2025"}));
}

TEST(MaterialReference, DocsHoldTheReferenceGeneratedFromTheKinds) {
  std::ifstream in(GLINTLAB_SOURCE_DIR "/docs/scene-format.md", std::ios::binary);
  ASSERT_TRUE(in) << "cannot read docs/scene-format.md";
  std::stringstream s;
  s << in.rdbuf();
  const std::string docs = s.str();
  const std::string begin_marker = "<!-- generated:material-reference -->\n";
  const std::string end_marker = "<!-- /generated:material-reference -->\n";
  const auto begin = docs.find(begin_marker), end = docs.find(end_marker);
  ASSERT_NE(begin, std::string::npos) << "docs/scene-format.md lacks the line " << begin_marker;
  ASSERT_NE(end, std::string::npos) << "docs/scene-format.md lacks the line " << end_marker;
  ASSERT_LT(begin, end);
  const std::string block = docs.substr(begin + begin_marker.size(), end - begin - begin_marker.size());
  const std::string generated = material_reference_markdown(all_material_kinds());
  EXPECT_TRUE(block == generated) << "docs/scene-format.md's material-kind reference differs from the declarations ("
                                  << first_difference(block, generated) << "); regenerate it:\n"
                                  << "  tools/update-reference-docs.sh";
  // Every key of every kind has its row.
  for (const MaterialKind& k : all_material_kinds()) {
    EXPECT_NE(generated.find("### `type = \"" + k.id + "\"`"), std::string::npos) << k.id;
    for (const MaterialParamDecl& p : k.params)
      if (!p.derived) {
        EXPECT_NE(generated.find("| `" + p.key + "` | number |"), std::string::npos) << p.key;
      }
  }
}

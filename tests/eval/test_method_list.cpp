// --methods with configured variants (shading/method_list.hpp): names, file names, parameter
// precedence, and every class of bad entry with a message naming it.
#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <set>

#include "core/error.hpp"
#include "shading/method_list.hpp"
#include "shading/registry.hpp"

using namespace glintlab;

namespace {

float choice_index(const MethodDescriptor& m, const std::string& param, const std::string& choice) {
  const auto& choices = m.find_param(param)->choices;
  return static_cast<float>(std::find(choices.begin(), choices.end(), choice) - choices.begin());
}

void expect_rejected(const std::string& list, std::initializer_list<const char*> fragments,
                     const std::vector<std::string>& params = {}) {
  try {
    resolve_methods(list, params);
    ADD_FAILURE() << "'" << list << "' was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const char* f : fragments)
      EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
  }
}

}  // namespace

TEST(MethodList, PlainMethodsAreTheirIdsEverywhere) {
  const auto v = parse_method_variants("conventional,lean");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[1].method->id, "lean");
  EXPECT_EQ(v[1].name, "lean");
  EXPECT_EQ(v[1].file_name, "lean");
  EXPECT_TRUE(v[1].settings.empty());
  EXPECT_EQ(parse_method_variants("all").size(), all_methods().size());
  const auto with_variant = parse_method_variants("all,podee{area=lens}");
  EXPECT_EQ(with_variant.size(), all_methods().size() + 1);
  EXPECT_EQ(with_variant.back().name, "podee{area=lens}");
}

TEST(MethodList, VariantsShareTheirMethodAndDifferInTheirSettings) {
  const auto v = parse_method_variants("podee,podee{glossy=off,area=lens},podee{corner_lod=-2}");
  ASSERT_EQ(v.size(), 3u);
  for (const auto& x : v) EXPECT_EQ(x.method, &find_method("podee"));
  EXPECT_EQ(v[1].name, "podee{glossy=off,area=lens}");
  EXPECT_EQ(v[1].file_name, "podee.glossy=off.area=lens");  // the order written, as --param podee.glossy=off
  EXPECT_EQ(v[2].file_name, "podee.corner_lod=-2");
  ASSERT_EQ(v[1].settings.size(), 2u);
  EXPECT_EQ(v[1].settings[0], (std::pair<std::string, std::string>{"glossy", "off"}));

  const MethodDescriptor& podee = find_method("podee");
  const auto c = resolve_methods("podee,podee{glossy=off,area=lens}", {});
  EXPECT_EQ(c[0].params.at("area"), choice_index(podee, "area", "exact"));
  EXPECT_EQ(c[1].params.at("area"), choice_index(podee, "area", "lens"));
  EXPECT_EQ(c[1].params.at("glossy"), choice_index(podee, "glossy", "off"));
  EXPECT_EQ(c[1].params.at("corner_lod"), c[0].params.at("corner_lod")) << "what the variant leaves is the default";
  EXPECT_EQ(c[1].display_name(), "podee{glossy=off,area=lens}");
  EXPECT_EQ(c[1].file_stem(), "podee.glossy=off.area=lens");
  EXPECT_EQ(c[0].file_stem(), "podee");
}

TEST(MethodList, AVariantsSettingsWinOverParamWhichAppliesToTheRest) {
  const MethodDescriptor& podee = find_method("podee");
  const float lens = choice_index(podee, "area", "lens"), circle = choice_index(podee, "area", "circle");
  for (const std::string param : {"podee.area=circle", "area=circle"}) {
    const auto c = resolve_methods("conventional,podee,podee{area=lens}", {param, "podee.corner_lod=-3"});
    EXPECT_EQ(c[1].params.at("area"), circle) << param;
    EXPECT_EQ(c[2].params.at("area"), lens) << param << ": the variant's own setting wins";
    EXPECT_EQ(c[2].params.at("corner_lod"), -3.0f) << "--param sets what the variant leaves";
  }
  // Among --params the last one wins.
  EXPECT_EQ(resolve_methods("podee", {"area=lens", "area=circle"})[0].params.at("area"), circle);
  // A bad --param value is an error even where a variant overrides it.
  expect_rejected("podee{area=lens}", {"--param", "area=square", "exact|circle|lens"}, {"podee.area=square"});
}

TEST(MethodList, DistinctNamesGetDistinctFileNames) {
  const auto v = parse_method_variants(
      "chermain2021,chermain2021{lean=off},chermain2021{lean=off,kernel=1},chermain2021{kernel=1,lean=off},"
      "chermain2021{kernel=1}");
  std::set<std::string> files;
  for (const auto& x : v) files.insert(x.file_name);
  EXPECT_EQ(files.size(), v.size());
}

TEST(MethodList, BadEntriesNameTheEntryTheParameterAndWhatIsAllowed) {
  // Braces.
  expect_rejected("podee{area=lens", {"--methods 'podee{area=lens'", "'{' without its '}'", "id{name=value,...}"});
  expect_rejected("conventional,podee}", {"'}' without its '{'", "'podee}'"});
  expect_rejected("podee{area={lens}}", {"braces inside braces"});
  expect_rejected("podee{area=lens}x", {"text after '}'", "'podee{area=lens}x'"});
  expect_rejected("{area=lens}", {"no method before '{'"});
  // Methods.
  expect_rejected("magic{x=1}", {"unknown method 'magic'", "conventional", "podee"});
  expect_rejected("magic", {"unknown method 'magic'"});
  // Settings.
  expect_rejected("podee{}", {"nothing between the braces of 'podee{}'", "corners, origin, area"});
  expect_rejected("podee{area}", {"'area'", "is not name=value", "podee's parameters"});
  expect_rejected("podee{=lens}", {"'=lens'", "is not name=value"});
  expect_rejected("podee{area=}", {"'area='", "is not name=value"});
  expect_rejected("podee{area=lens,}", {"'' in 'podee{area=lens,}' is not name=value"});
  expect_rejected("podee{bogus=1}", {"--methods 'podee{bogus=1}'", "no parameter 'bogus'", "corner_lod"});
  expect_rejected("podee{area=square}", {"'podee{area=square}'", "area=square", "not a choice", "exact|circle|lens"});
  expect_rejected("podee{corner_lod=5}", {"corner_lod=5", "out of range", "-16 .. 0"});
  expect_rejected("podee{corner_lod=deep}", {"corner_lod=deep", "not a number", "-16 .. 0"});
  expect_rejected("podee{corner_lod= -1}", {"' -1'", "corner_lod", "-16 .. 0"});
  expect_rejected("podee{area=lens,area=circle}", {"parameter 'area' is set twice", "'podee{area=lens,area=circle}'"});
  // Names.
  expect_rejected("podee,lean,podee", {"'podee' is listed twice"});
  expect_rejected("podee{area=lens},podee{area=lens}", {"'podee{area=lens}' is listed twice"});
  expect_rejected("all,lean", {"'lean' is listed twice", "'all' holds every method"});
  // Entries.
  for (const char* list : {"", ",podee", "podee,", "podee,,lean"}) expect_rejected(list, {"an empty entry", "'all'"});
}

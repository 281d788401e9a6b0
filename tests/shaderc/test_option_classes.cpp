// Every command-line option of prism-shaderc is classified, once, as changing the outputs or
// not (output_options.hpp): the parser's options are enumerated, so a new option without a
// row fails here before it can slip past the run record (up_to_date.hpp).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "args.hpp"
#include "output_options.hpp"

using prism::shaderc::commandLineOptionNames;
using prism::shaderc::OptionEffect;
using prism::shaderc::optionRule;
using prism::shaderc::optionRules;

TEST(OptionClasses, EveryParserOptionIsClassified) {
    const auto names = commandLineOptionNames();
    ASSERT_GT(names.size(), 20u) << "the parser's options were not enumerated";
    for (const auto& name : names)
        EXPECT_NE(optionRule(name), nullptr)
            << "option " << name << " has no row in output_options.cpp: say whether it changes the outputs";
}

TEST(OptionClasses, EveryRowNamesAParserOptionOnce) {
    const auto names = commandLineOptionNames();
    const std::set<std::string> known(names.begin(), names.end());
    std::set<std::string_view> seen;
    for (const auto& rule : optionRules()) {
        EXPECT_TRUE(known.count(std::string(rule.name)))
            << rule.name << " is classified but the parser has no such option";
        EXPECT_TRUE(seen.insert(rule.name).second) << rule.name << " is classified twice";
        EXPECT_EQ(rule.lines != nullptr, rule.effect == OptionEffect::ChangesOutputs)
            << rule.name << ": a row that changes outputs says how it is recorded, and only such a row";
    }
}

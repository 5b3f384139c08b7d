// The fold weights file: what tune --fold-weights writes, eval --weights-per-set reads back.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "eval/set_weights_file.hpp"
#include "match/weights.hpp"

using namespace arg;

TEST(SetWeightsFile, ReadsBackWhatItWrites) {
  const std::string panorama = format_weights(parse_weights("arg panorama=1.5"));
  const std::vector<SetWeights> folds = {{"shrec07", panorama}, {"psb_soups", "graph"}};
  const std::vector<SetWeights> back = parse_set_weights(format_set_weights(folds));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].set, "shrec07");
  EXPECT_EQ(back[0].weights, panorama);
  EXPECT_EQ(back[1].set, "psb_soups");
  EXPECT_EQ(back[1].weights, "graph");
}

TEST(SetWeightsFile, SkipsCommentsAndBlankLines) {
  const auto folds = parse_set_weights("# learnt by tune\n\nshrec11\targ spectrum=0.35\r\n");
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_EQ(folds[0].set, "shrec11");
  EXPECT_EQ(folds[0].weights, "arg spectrum=0.35");
}

TEST(SetWeightsFile, ABadLineIsNamed) {
  auto message = [](const std::string& text) {
    try {
      parse_set_weights(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("shrec07 arg\nshrec11\n").find("line 2: a set name without weights"),
            std::string::npos);
  EXPECT_NE(message("shrec07 panorama=-1\n").find("line 1: "), std::string::npos);
  EXPECT_NE(message("a arg\n# x\na graph\n").find("line 3: set a named twice"), std::string::npos);
}

// io/spelling.hpp: the edit distance by hand and the suggestions a typo gets.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "selfalign/io/spelling.hpp"

namespace selfalign {
namespace {

TEST(Spelling, EditDistanceByHand) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("width", "widht"), 2u);  // a swap is two edits (Levenshtein)
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("design", "desing"), 2u);
  EXPECT_EQ(edit_distance(std::string(65, 'a'), "a"), static_cast<std::size_t>(-1));
}

TEST(Spelling, ClosestNameIgnoresCaseAndUnderscores) {
  const std::vector<std::string> subcommands = {"simulate", "steady", "design", "montecarlo"};
  EXPECT_EQ(closest_name("desing", subcommands), "design");
  EXPECT_EQ(closest_name("SIMULATE", subcommands), "simulate");
  EXPECT_EQ(closest_name("simulat", subcommands), "simulate");
  EXPECT_EQ(closest_name("optimise", subcommands), "");  // nothing within two edits
  EXPECT_EQ(closest_name("st", subcommands), "");         // too short to guess
  const std::vector<std::string> flags = {"c-mu", "x-mu", "mu-static", "config"};
  EXPECT_EQ(closest_name("c_mu", flags), "c-mu");
  EXPECT_EQ(closest_name("mu_static", flags), "mu-static");
}

}  // namespace
}  // namespace selfalign

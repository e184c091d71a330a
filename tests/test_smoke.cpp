#include <gtest/gtest.h>
#include "selfalign/profiles/three_phase.hpp"
TEST(Smoke, Builds) { EXPECT_TRUE(selfalign::solve_three_phase({1, 0.084, 3, 0.9}).physical); }

// error.hpp: the one exception type and the mapping of the library's parameter names to the
// user's (renamed, with_user_names), on hand-made messages.
#include <gtest/gtest.h>

#include <string>

#include "selfalign/error.hpp"

namespace selfalign {
namespace {

constexpr UserName kNames[] = {{"accels", "accelerations"},
                               {"mu_static", "friction.static"},
                               {"mu_kinetic", "friction.kinetic"}};

TEST(InvalidParameter, RenamedNamesTheUsersKeyKeepingIndexValueAndRange) {
  const InvalidParameter e = renamed(InvalidParameter("accels[2]", 1.5, "must be finite"), kNames);
  EXPECT_EQ(std::string(e.what()), "invalid accelerations[2] = 1.5: must be finite");
  EXPECT_EQ(e.value(), "1.5");
  // Each part of a pair; a name not in the table gets the prefix (a file's section).
  const InvalidParameter pair =
      renamed(InvalidParameter("mu_static, mu_kinetic", "1, 1.2", "static >= kinetic"), kNames);
  EXPECT_EQ(pair.name(), "friction.static, friction.kinetic");
  EXPECT_EQ(renamed(InvalidParameter("period", 0.0, "must be > 0"), kNames, "table.x.").name(),
            "table.x.period");
  EXPECT_EQ(renamed(InvalidParameter("accelsx", 0.0, "?"), kNames).name(), "accelsx");
}

TEST(InvalidParameter, WithUserNamesRethrowsRenamedAndPassesResults) {
  EXPECT_EQ(with_user_names(kNames, [] { return 7; }), 7);
  try {
    with_user_names(kNames, [] { throw InvalidParameter("mu_static", 0.1, "must be >= mu"); });
    FAIL() << "no exception";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(std::string(e.what()), "invalid friction.static = 0.1: must be >= mu");
  }
}

}  // namespace
}  // namespace selfalign

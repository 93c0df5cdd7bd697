// The collector reports every problem of an input at once, each a complete InputError.

#include "motoflex/core/error_collector.hpp"

#include <gtest/gtest.h>

#include <string>

namespace motoflex {
namespace {

TEST(ErrorCollector, CollectsEveryPartsErrorAndGoesOn) {
  ErrorCollector errors;
  int parts_run = 0;
  EXPECT_FALSE(errors.check([&] {
    ++parts_run;
    throw InputError("robot.yaml", 3, "urdf", "missing");
  }));
  EXPECT_TRUE(errors.check([&] { ++parts_run; }));
  EXPECT_FALSE(errors.check([&] {
    ++parts_run;
    throw InputError("robot.yaml", 9, "feet", "unknown link 'x'");
  }));
  EXPECT_EQ(parts_run, 3);
  ASSERT_EQ(errors.size(), 2u);
  try {
    errors.throw_if_any();
    FAIL() << "two problems must throw";
  } catch (const InputErrors& all) {
    ASSERT_EQ(all.errors().size(), 2u);
    EXPECT_EQ(std::string(all.errors()[0].what()), "robot.yaml:3: urdf: missing");
    EXPECT_EQ(std::string(all.errors()[1].what()), "robot.yaml:9: feet: unknown link 'x'");
    EXPECT_EQ(std::string(all.what()), "robot.yaml:3: urdf: missing (and 1 more)");
  }
}

TEST(ErrorCollector, OneProblemIsThrownAsItselfAndDuplicatesCountOnce) {
  ErrorCollector errors;
  errors.add("a.yaml", 1, "x", "bad");
  errors.add("a.yaml", 1, "x", "bad");
  EXPECT_EQ(errors.size(), 1u);
  try {
    errors.throw_if_any();
    FAIL();
  } catch (const InputErrors&) {
    FAIL() << "a single problem is a plain InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "a.yaml:1: x: bad");
  }
  ErrorCollector none;
  EXPECT_NO_THROW(none.throw_if_any());
}

TEST(ErrorCollector, NestedCollectionsFlattenIntoTheirProblems) {
  ErrorCollector inner;
  inner.add("a.yaml", 1, "x", "one");
  inner.add("a.yaml", 2, "y", "two");
  ErrorCollector outer;
  outer.check([&] { inner.throw_if_any(); });
  outer.add("b.yaml", 5, "z", "three");
  EXPECT_EQ(outer.size(), 3u);
}

}  // namespace
}  // namespace motoflex

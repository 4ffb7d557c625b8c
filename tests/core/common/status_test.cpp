#include "core/common/status.h"

#include <gtest/gtest.h>

namespace sightline {
namespace {

TEST(Status, OkByDefault) {
  Status s;
  EXPECT_TRUE(s.ok());
  EXPECT_EQ(s.ToString(), "ok");
}

TEST(Status, CarriesCodeAndMessageWithContext) {
  Status s = ParseError("line 3: expected 12 numbers").WithContext("calib.txt");
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.ToString(), "parse error: calib.txt: line 3: expected 12 numbers");
}

Status FailsEarly(bool fail, int* reached) {
  SIGHTLINE_RETURN_IF_ERROR(fail ? NotFound("x") : Status::Ok());
  *reached = 1;
  return Status::Ok();
}

TEST(Status, ReturnIfErrorStopsOnError) {
  int reached = 0;
  EXPECT_EQ(FailsEarly(true, &reached).code(), StatusCode::kNotFound);
  EXPECT_EQ(reached, 0);
  EXPECT_TRUE(FailsEarly(false, &reached).ok());
  EXPECT_EQ(reached, 1);
}

TEST(StatusOr, HoldsValueOrError) {
  StatusOr<int> v = 7;
  ASSERT_TRUE(v.ok());
  EXPECT_EQ(*v, 7);
  StatusOr<int> e = Unavailable("no device");
  EXPECT_FALSE(e.ok());
  EXPECT_EQ(e.status().message(), "no device");
}

}  // namespace
}  // namespace sightline

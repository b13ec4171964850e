// Tests of measure_run.h: options are checked before any reading, and a picture is quantised and
// measured as its pixels say.
#include "app/measure_run.h"

#include <gtest/gtest.h>

#include "curdle/error.h"
#include "picture_support.h"

namespace curdle::app {
namespace {

TEST(MeasureRun, OptionsAreCheckedAndAPictureIsMeasured) {
  EXPECT_THROW(check_base(1), InputError);
  EXPECT_THROW(check_base(65), InputError);
  EXPECT_NO_THROW(check_base(64));
  MeasureRequest bad;
  bad.values = 17;
  EXPECT_THROW(check_measure_options(bad), InputError);
  bad.values = 2, bad.threshold = 1.5;
  EXPECT_THROW(check_measure_options(bad), InputError);

  const auto dir = test::scratch("measure-run");
  // A black square in the top-left quarter of a white 32 x 32 picture.
  MeasureRequest request;
  request.image = test::write_file(dir / "square.png", test::grey_png(32, 32, [](int x, int y) {
                                     return x < 16 && y < 16 ? 0 : 255;
                                   }));
  const MeasuredPicture picture = run_measure(request);
  EXPECT_EQ(picture.source, "square.png");
  ASSERT_EQ(picture.levels.size(), 2u);
  EXPECT_LT(picture.levels[1], picture.levels[0]);  // value 1 is the darker
  uint64_t dark = 0;
  for (const auto& v : picture.measurement.values)
    if (v.value == 1) dark = v.count;
  EXPECT_EQ(dark, 256u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curdle::app

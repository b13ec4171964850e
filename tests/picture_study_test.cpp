// Tests of picture_study.h: an upload's name is kept safe, and a picture sent as bytes is
// measured and fitted in the lattice's own cells.
#include "app/picture_study.h"

#include <gtest/gtest.h>

#include "curdle/error.h"
#include "picture_support.h"

namespace curdle::app {
namespace {

TEST(PictureStudy, UploadNamesAreSafeAndPicturesAreFittedInCells) {
  EXPECT_EQ(upload_name("../../etc/passwd"), "passwd");
  EXPECT_EQ(upload_name("façade 1.png"), "fa--ade-1.png");  // each byte of ç
  EXPECT_EQ(upload_name(""), "picture");
  EXPECT_LE(upload_name(std::string(300, 'a')).size(), 64u);

  PictureStudyRequest request;
  // A 16 x 16 picture whose left half is dark, its edge staggered so that it is not cells of
  // several pixels: 8 dark pixels in even rows, 7 in odd ones.
  request.bytes = test::grey_png(16, 16, [](int x, int y) { return x + y % 2 < 8 ? 0 : 255; });
  request.name = "half.png";
  request.base = 2, request.stages = 4, request.curds = 1;
  const PictureStudy study = study_picture(request);
  EXPECT_EQ(study.fitted.lattice.stages, 4);
  ASSERT_EQ(study.fitted.curds.size(), 1u);
  ASSERT_EQ(study.fitted.curds[0].fit.stages.size(), 4u);
  EXPECT_EQ(study.fitted.curds[0].fit.stages.back().measured, 120u);
  EXPECT_NE(study.fitted.toml.find("[lattice]"), std::string::npos);
  request.bytes = "not a picture";
  EXPECT_THROW(study_picture(request), InputError);
  request.bytes = test::grey_png(16, 16, [](int, int) { return 0; });
  request.max_pixels = 100;
  EXPECT_THROW(study_picture(request), ResourceLimitError);
}

}  // namespace
}  // namespace curdle::app

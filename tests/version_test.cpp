// libcurdle.so as another program links it: its version, and a run through the public headers
// alone (the include path is the installed one's layout: src/ and the project root).
#include "app/version.h"

#include <gtest/gtest.h>

#include "app/generated_run.h"
#include "curdle/error.h"

namespace curdle::app {
namespace {

TEST(Library, VersionIsTheProjects) { EXPECT_STREQ(version(), CURDLE_PROJECT_VERSION); }

TEST(Library, RunsARecipeThroughThePublicHeaders) {
  const app::Run run =
      resolve_run({.recipe_text = "name = \"lib\"\n[lattice]\nbase = 2\n"
                                  "dimension = 2\nstages = 3\n[[curds]]\nname = "
                                  "\"dark\"\nprobabilities = [\"1/2\", \"1/2\", \"1/2\"]\n",
                   .recipe_path = "lib.toml",
                   .seed = "3"});
  const GeneratedRun g = generate_run(run, true, 1, nullptr);
  EXPECT_EQ(g.report.seed, 3u);
  EXPECT_NE(output_bytes(g, "cells.csv").find("x,y,value,dark"), std::string::npos);
  EXPECT_THROW(output_bytes(g, "layout.svg"), InputError);
}

}  // namespace
}  // namespace curdle::app

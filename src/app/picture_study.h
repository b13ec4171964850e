// A picture sent as bytes (the page's upload), measured and fitted in one read: the values it
// is quantised to are the 2^n of the curds fitted, and boxes have the lattice's base, so that
// the measured counts and the fitted recipe speak of the same cells.
#pragma once

#include <cstdint>
#include <string>

#include "app/fit_run.h"
#include "export/report/measure_files.h"

namespace curdle::app {

struct PictureStudyRequest {
  std::string bytes;  // the picture's file, as sent
  std::string name;   // its file name as the user knows it: messages, the recipe's name
  int base = 2;       // lattice base, and the boxes' base
  int stages = 1;     // stages fitted
  int curds = 1;      // curds fitted; the picture is quantised to 2^curds values
  int states = 0;     // or one Markov curd of this many states: S + 1 tones (fit_run.h)
  uint64_t max_pixels = uint64_t{1} << 22;
  uint64_t max_memory = 0;  // bytes; 0: default_memory_limit()
};

struct PictureStudy {
  MeasuredPicture measured;
  FittedRecipe fitted;
};

// InputError for a picture that cannot be read or options out of range; ResourceLimitError
// above max_pixels or max_memory.
PictureStudy study_picture(const PictureStudyRequest& request);

// The upload's name kept to what is safe in messages and file names: its last path part, in
// letters, digits, '.', '-' and '_' (others become '-'), at most 64 characters; "picture" when
// nothing is left.
std::string upload_name(const std::string& name);

}  // namespace curdle::app

// Long work stopped part-way, as the shells see it: the server installs a rule for each
// request (its budget, its client) and answers WorkStopped as 503. The mechanism is the core's
// (curdle/stop.h), so that layouts and writers can stop without knowing who asked.
#pragma once

#include "curdle/stop.h"

namespace curdle::app {

using curdle::StopRule;
using curdle::StopScope;
using curdle::WorkStopped;

}  // namespace curdle::app

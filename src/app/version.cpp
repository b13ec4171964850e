#include "app/version.h"

namespace curdle::app {

const char* version() { return CURDLE_VERSION; }

}  // namespace curdle::app

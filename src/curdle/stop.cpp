#include "curdle/stop.h"

namespace curdle {

StopScope::StopScope(StopRule& rule) : StopScope(&rule) {}

StopScope::StopScope(StopRule* rule) : outer_(detail::stop_state.rule) {
  if (!rule) return;
  detail::stop_state.rule = rule;
  detail::stop_state.countdown = 0;
}

StopScope::~StopScope() { detail::stop_state.rule = outer_; }

namespace detail {

void ask_stop_rule() {
  stop_state.countdown = 255;
  if (auto reason = stop_state.rule->stop_reason()) throw WorkStopped(*reason);
}

}  // namespace detail
}  // namespace curdle

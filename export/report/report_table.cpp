#include "export/report/report_table.h"

#include <fmt/format.h>

#include <cmath>

namespace curdle {
namespace {

std::string number(const std::optional<double>& x, int decimals = 3) {
  return x ? fmt::format("{:.{}f}", *x, decimals) : std::string("-");
}

// A Markov curd: per stage and state the count beside its theory and z; per set the box counts
// beside theirs, the fitted dimensions, the stationary limit and the chance of extinction.
void add_markov(std::string& out, const MarkovReport& m, int stages) {
  auto line = [&](const std::string& s) { out += s + "\n"; };
  line("");
  std::string states = "dead";
  for (const std::string& s : m.states) states += ", " + s;
  line(fmt::format("Markov curd '{}': states {}; {} P; {}", m.name, states,
                   m.stationary ? "stationary" : "stage-wise",
                   m.wheys ? "wheys: dead cells can come back" : "dead is absorbing"));
  line(fmt::format("  {:>5} {:<14} {:>10} {:>12} {:>12} {:>10} {:>7}", "stage", "state", "share",
                   "count", "expected", "sd", "z"));
  for (const StateStageRow& s : m.stages)
    line(fmt::format("  {:>5} {:<14} {:>10.6f} {:>12} {:>12.1f} {:>10.2f} {:>7}", s.stage, s.state,
                     s.share, s.count, s.expected, s.expected_sd, number(s.z, 2)));
  std::string head = fmt::format("  {:>5}", "level");
  for (const StateSet& set : m.sets) head += fmt::format(" {:>10} {:>10}", set.name, "expected");
  line(head);
  for (int k = 0; k <= stages; ++k) {
    std::string row = fmt::format("  {:>5}", k);
    for (const StateSet& set : m.sets)
      row += fmt::format(" {:>10} {:>10.1f}", set.box_counts[static_cast<size_t>(k)],
                         set.expected_box_counts[static_cast<size_t>(k)]);
    line(row);
  }
  for (const StateSet& set : m.sets)
    line(fmt::format(
        "  {}: box dimension fit {} (R^2 {}); expected at {} stages {}; limit {}; "
        "a root leaves none with chance {:.4g}",
        set.name, set.fit ? number(set.fit->slope) : "-", set.fit ? number(set.fit->r2, 4) : "-",
        stages, set.expected_fit ? number(set.expected_fit->slope) : "-",
        set.theory_dimension ? number(set.theory_dimension)
        : m.stationary       ? std::string("none: the set dies out")
                             : std::string("- (P changes with the stage)"),
        set.extinction));
  if (m.sd_is_approximate) line("  note: quota mode through a window; sd is the canonical value");
}

}  // namespace

std::string format_report_table(const Report& r) {
  std::string out;
  auto line = [&](const std::string& s) { out += s + "\n"; };
  std::string size;
  for (int d = 0; d < r.lattice.dimension; ++d)
    size += (d ? " x " : "") + std::to_string(r.view.size[d]);
  line(fmt::format("{} - seed {} - base {}, {}-D, {} stages, {} mode - {} cells ({})", r.recipe,
                   r.seed, r.lattice.base, r.lattice.dimension, r.lattice.stages,
                   to_string(r.lattice.mode), r.cells, size));
  for (const CurdReport& c : r.curds) {
    line("");
    line(fmt::format("curd '{}': P(final) = {:.6g}", c.name, c.final_probability));
    line(fmt::format("  {:>5} {:>9} {:>12} {:>12} {:>10} {:>12} {:>12} {:>8} {:>8} {:>8}", "stage",
                     "p", "survivors", "expected", "sd", "box count", "expected", "local D",
                     "logN/klb", "theory D"));
    for (const StageRow& s : c.stages)
      line(
          fmt::format("  {:>5} {:>9} {:>12} {:>12.1f} {:>10.2f} {:>12} {:>12.1f} {:>8} {:>8} {:>8}",
                      s.stage, s.probability.text(), s.survivors, s.expected, s.expected_sd,
                      s.box_count, s.expected_box_count, number(s.local_dimension),
                      number(s.mean_dimension), number(s.theory_dimension)));
    for (const StageRow& s : c.stages)
      if (s.quota_missed)
        line(
            fmt::format("  stage {}: the quota of {} was not reached, {} survive: the children of "
                        "the survivors inside the field are fewer",
                        s.stage, *s.quota_missed, s.survivors));
    // The fit beside what the same fit gives on the expected counts at these stages and in this
    // view, and the limit of many stages: a crop or few stages move the first, not the last.
    line(
        fmt::format("  box dimension: fit {} (R^2 {}, {} levels); expected at {} stages {}; "
                    "limit {}",
                    c.fit ? number(c.fit->slope) : "-", c.fit ? number(c.fit->r2, 4) : "-",
                    c.fit ? c.fit->points : 0, r.lattice.stages,
                    c.expected_fit ? number(c.expected_fit->slope) : "-",
                    c.dies_out ? std::string("none: run on, the curd dies out almost surely")
                               : number(c.theory_dimension)));
    // Shown when the view cuts boxes, so that the two fits differ.
    if (c.share_weighted_fit && c.fit &&
        std::fabs(c.share_weighted_fit->slope - c.fit->slope) > 1e-9)
      line(fmt::format(
          "  boxes the view cuts weighted by the share it shows: fit {}; expected {}",
          number(c.share_weighted_fit->slope),
          c.expected_share_weighted_fit ? number(c.expected_share_weighted_fit->slope) : "-"));
  }
  for (const MarkovReport& m : r.markov) add_markov(out, m, r.lattice.stages);
  line("");
  line(fmt::format("  {:>6} {:<28} {:>12} {:>12}", "value", "curds", "count", "expected"));
  const bool all = r.values.size() <= 64;
  size_t hidden = 0;
  for (const ValueRow& v : r.values) {
    // Codes a Markov curd's planes can hold but no state has never occur.
    if (v.count == 0 && v.expected == 0 && !r.markov.empty()) continue;
    if (!all && v.count == 0) {
      ++hidden;
      continue;
    }
    line(fmt::format("  {:>6} {:<28} {:>12} {:>12.1f}", v.value, v.label, v.count, v.expected));
  }
  if (hidden) line(fmt::format("  ({} values with no cells not shown)", hidden));
  if (r.sd_is_approximate) line("  note: quota mode through a window; sd is the canonical value");
  return out;
}

}  // namespace curdle

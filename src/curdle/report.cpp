#include "curdle/report.h"

#include <algorithm>
#include <cmath>

#include "curdle/curdling.h"
#include "curdle/density_theory.h"
#include "curdle/extinction.h"
#include "curdle/markov.h"
#include "curdle/overlay.h"
#include "curdle/theory.h"

namespace curdle {
namespace {

std::optional<double> finite(double x) {
  if (std::isfinite(x)) return x;
  return std::nullopt;
}

// With a density field, each finest cell has its own chances: the values' expected counts are
// summed cell by cell (curds are independent). Empty when no curd has a field.
std::vector<double> expected_values_with_density(const Design& design, const Box& view) {
  const auto& curds = design.curds;
  if (std::none_of(curds.begin(), curds.end(), [](const CurdSpec& c) { return c.density; }))
    return {};
  const Lattice& l = design.lattice;
  // A Markov curd (no density field) takes its state shares, the same in every cell.
  const std::vector<CurdGroup> groups = curd_groups(curds);
  std::vector<double> P(curds.size());
  std::vector<std::vector<double>> shares(groups.size());
  for (size_t g = 0; g < groups.size(); ++g) {
    if (groups[g].chain) {
      shares[g] = state_shares(*groups[g].chain, l.stages);
      shares[g].resize(size_t{1} << groups[g].planes, 0.0);
    } else {
      P[groups[g].first] = survival_probability(curds[groups[g].first].probabilities, l.stages);
    }
  }
  std::vector<double> expected(size_t{1} << curds.size(), 0.0), alive(curds.size());
  for (int64_t z = 0; z < view.size[2]; ++z)
    for (int64_t y = 0; y < view.size[1]; ++y)
      for (int64_t x = 0; x < view.size[0]; ++x) {
        const Coord cell{view.origin[0] + x, view.origin[1] + y, view.origin[2] + z};
        for (size_t c = 0; c < curds.size(); ++c)
          alive[c] = curds[c].density ? curds[c].density->survival(l, l.stages, cell, P[c]) : P[c];
        for (uint32_t v = 0; v < expected.size(); ++v) {
          double p = 1;
          for (size_t g = 0; g < groups.size(); ++g) {
            const size_t c = groups[g].first;
            const uint32_t state = groups[g].state(v);
            p *= groups[g].chain ? shares[g][state] : state ? alive[c] : 1 - alive[c];
          }
          expected[v] += p;
        }
      }
  return expected;
}

// The report's row of every stage of one curd: survivors and box counts beside their
// expectations (with the curd's density field when it has one), and the dimensions.
void add_stage_rows(CurdReport& cr, const Design& design, const CurdSpec& spec, const Curd& curd,
                    const DensityExpectation* density, const Box& view, bool sd_is_approximate) {
  const Lattice& l = design.lattice;
  const bool quota = l.mode == Mode::quota;
  const double log_b = std::log(static_cast<double>(l.base));
  uint64_t previous = cr.roots;
  // Per root cell meeting the view: N_k <= R b^(E k), so the ratio never exceeds E.
  const double roots = static_cast<double>(cells_meeting(l, 0, view));
  for (int k = 1; k <= l.stages; ++k) {
    StageRow row;
    row.stage = k;
    row.probability = spec.probabilities[k - 1];
    row.cells = cells_meeting(l, k, view);
    // The finest level's box count is its survivors: no second pass over the largest stage.
    row.survivors = k == l.stages ? cr.box_counts[k] : count_survivors(curd, k, l.children());
    row.expected = density ? density->survivors[static_cast<size_t>(k)]
                           : expected_survivors(l, spec.probabilities, k, view);
    row.expected_sd = density                       ? density->survivors_sd[static_cast<size_t>(k)]
                      : quota && !sd_is_approximate ? 0.0
                                                    : survivors_sd(l, spec.probabilities, k, view);
    if (quota && !sd_is_approximate) {
      const uint64_t target =
          quota_target(spec.probabilities, k, cells_meeting(l, k, design.field));
      if (row.survivors < target) {
        // Not every target fits in the field: then the count varies, as canonical's does.
        row.quota_missed = target;
        row.expected_sd = survivors_sd(l, spec.probabilities, k, view);
      }
    }
    row.box_count = cr.box_counts[k];
    row.expected_box_count = cr.expected_box_counts[static_cast<size_t>(k)];
    if (row.survivors > 0 && previous > 0)
      row.local_dimension = std::log(static_cast<double>(row.survivors) / previous) / log_b;
    if (row.survivors > 0)
      row.mean_dimension = std::log(static_cast<double>(row.survivors) / roots) / (k * log_b);
    row.theory_dimension = finite(theory_dimension(l, row.probability.value()));
    previous = row.survivors;
    cr.stages.push_back(row);
  }
}

}  // namespace

Report make_report(const Design& design, uint64_t seed, const CurdField& generated,
                   const Box& view) {
  const Lattice& l = design.lattice;
  // Quota mode generates the whole field; count only what the view shows.
  const bool restrict = !(generated.generated == view);
  const CurdField restricted = restrict ? restrict_to(generated, view) : CurdField{};
  const CurdField& field = restrict ? restricted : generated;

  Report report;
  report.recipe = design.name;
  report.seed = seed;
  report.lattice = l;
  report.field = design.field;
  report.view = view;
  report.cells = view.cells();
  const bool quota = l.mode == Mode::quota;
  report.sd_is_approximate = quota && !(view == design.field);

  std::vector<Bitset> scratch;
  // Share-weighted box counts, for views of up to 2^24 cells. A view of whole root cells cuts
  // no box, so its weighted counts are its counts and the fits are the plain ones; otherwise
  // the view's values (two bytes a cell) are read once for every curd.
  constexpr uint64_t kWeightedUpTo = uint64_t{1} << 24;
  const bool weighted = view.cells() <= kWeightedUpTo;
  const auto root = static_cast<int64_t>(l.side_in_cells(0));
  bool cuts_boxes = false;
  for (int d = 0; d < l.dimension; ++d)
    cuts_boxes |= view.origin[d] % root != 0 || view.size[d] % root != 0;
  const std::vector<uint16_t> values =
      weighted && cuts_boxes ? values_in(field, view) : std::vector<uint16_t>{};
  for (const CurdGroup& g : curd_groups(design.curds))
    if (g.chain) report.markov.push_back(make_markov_report(design, g, field, view));
  for (size_t c = 0; c < design.curds.size(); ++c) {
    const CurdSpec& spec = design.curds[c];
    if (spec.chain) continue;
    const Curd& curd = field.curds[c];
    CurdReport cr;
    cr.name = spec.name;
    cr.box_counts = box_counts(curd, l.children(), scratch);
    cr.roots = curd.stages[0].count();
    cr.root_box_count = cr.box_counts[0];
    // A density field changes every expectation (density_theory.h).
    const bool dense = spec.density.has_value();
    const DensityExpectation density =
        dense ? expect_with_density(l, spec.probabilities, *spec.density, view)
              : DensityExpectation{};
    cr.expected_box_counts =
        dense ? density.box_counts : expected_box_counts(l, spec.probabilities, view);
    add_stage_rows(cr, design, spec, curd, dense ? &density : nullptr, view,
                   report.sd_is_approximate);
    cr.fit = fit_box_dimension(cr.box_counts, l.base);
    cr.expected_fit = fit_box_dimension(cr.expected_box_counts, l.base);
    if (weighted && !cuts_boxes) {
      cr.share_weighted_fit = cr.fit;
      cr.expected_share_weighted_fit = cr.expected_fit;
    } else if (weighted) {
      std::vector<bool> cells(values.size());
      for (size_t i = 0; i < values.size(); ++i) cells[i] = values[i] >> c & 1;
      cr.share_weighted_fit = fit_box_dimension(share_weighted_box_counts(l, view, cells), l.base);
      // Its expectation is known for a plain curd only; a density field leaves it out.
      if (!dense)
        cr.expected_share_weighted_fit = fit_box_dimension(
            expected_share_weighted_box_counts(l, spec.probabilities, view), l.base);
    }
    cr.final_probability = survival_probability(spec.probabilities, l.stages);
    if (spec.density) cr.density = describe(*spec.density);
    const double mean_p = std::pow(cr.final_probability, 1.0 / l.stages);
    cr.dies_out = mean_p * static_cast<double>(l.children()) <= 1 + 1e-12;
    if (!cr.dies_out) cr.theory_dimension = finite(theory_dimension(l, mean_p));
    report.curds.push_back(std::move(cr));
  }

  // One curd's values are its final survivors and the rest: counted already.
  const std::vector<uint64_t> counts =
      design.curds.size() == 1 && !design.curds[0].chain
          ? std::vector<uint64_t>{field.generated.cells() - report.curds[0].box_counts.back(),
                                  report.curds[0].box_counts.back()}
          : value_counts(field);
  const double cells = static_cast<double>(cells_meeting(l, l.stages, view));
  const std::vector<double> expected_by_value = expected_values_with_density(design, view);
  const std::vector<double> shares = expected_value_shares(design);
  for (uint32_t v = 0; v < counts.size(); ++v) {
    ValueRow row;
    row.value = v;
    row.label = value_label(v, design.curds);
    row.count = counts[v];
    const double p = shares[v];
    row.expected = expected_by_value.empty() ? cells * p : expected_by_value[v];
    report.values.push_back(std::move(row));
  }
  return report;
}

}  // namespace curdle

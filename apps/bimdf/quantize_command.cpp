#include "quantize_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bimdf/io.hpp"
#include "number_checks.hpp"
#include "solve_command.hpp"

namespace bimdf::cli {
namespace {

using nlohmann::json;

std::string valence_counts(const quant::Layout& layout) {
  std::map<int, int> count;
  for (const quant::Chart& c : layout.charts)
    if (!c.empty()) ++count[c.valence()];
  std::string text;
  for (auto [k, n] : count)
    text += (text.empty() ? "" : ", ") + std::to_string(k) + "-sided " + std::to_string(n);
  return text;
}

json energies_json(const quant::Energies& e) {
  return {{"isometry", e.isometry},
          {"regularity", e.regularity},
          {"alignment", e.alignment},
          {"isometry_plus_regularity", e.isometry + e.regularity},
          {"regular_charts", e.regular_charts},
          {"charts", e.charts},
          {"aligned_pairs", e.aligned_pairs},
          {"pairs", e.pairs}};
}

json stats_json(const Solution& s) {
  json j = json::object();
  for (const auto& entry : s.stats)  // not a structured binding: clang 14 cannot capture one
    std::visit([&](const auto& v) { j[entry.first] = v; }, entry.second);
  return j;
}

}  // namespace

void add_layout_argument(CLI::App* cmd, std::string& layout) {
  cmd->add_option("LAYOUT", layout,
                  "The layout's triangle mesh NAME.obj; NAME.patch and NAME.corners (and, if "
                  "present, NAME.feature, NAME.c_feature) are read from beside it")
      ->required();
}

void add_quantize_options(CLI::App* cmd, QuantizeCommandOptions& o) {
  auto* scale = cmd->add_option("--scale", o.quantize.scale,
                                "Target edge length as a multiple of the mesh's average triangle "
                                "edge (QuadWild's scaleFact)")
                    ->default_val(1.0)
                    ->check(positive_number());
  auto* length = cmd->add_option("--edge-length", o.quantize.edge_length,
                                 "Absolute target edge length (in the mesh's units)")
                     ->check(positive_number());
  auto* faces = cmd->add_option("--target-faces", o.quantize.target_faces,
                                "Pick the edge length for about this many quads")
                    ->check(positive_whole_number());
  scale->excludes(length)->excludes(faces);
  length->excludes(faces);
  cmd->add_option("--alpha", o.quantize.model.alpha, "Isometry weight α; regularity gets 1 − α")
      ->default_val(0.005)
      ->check(number_from(0.0, 1.0));
  cmd->add_flag("--align,!--no-align", o.quantize.align,
                "Align singularities along chains of quads (default: on)");
  cmd->add_option("--align-weight", o.quantize.model.align_weight,
                  "Weight of singularity alignment (alignSingularitiesWeight)")
      ->default_val(0.1)
      ->check(non_negative_number());
  cmd->add_option("--nonquad-weight", o.quantize.model.nonquad_weight,
                  "Regularity weight of non-quad charts (regularityNonQuadrilateralsWeight)")
      ->default_val(0.9)
      ->check(non_negative_number());
  cmd->add_option("--unalign-weights", o.unalign_weights,
                  "Price of misalignment along chains in rounds 1 and 2 (unalign_weight of "
                  "paired_initial and paired_resolve)")
      ->expected(2)
      ->delimiter(',')
      ->default_str("2,4")
      ->check(non_negative_number());
  cmd->add_flag("--half-targets", o.half_targets,
                "Split an aligned side's target in the middle (flow_virtual_half) instead of "
                "where a triangle's regular pattern puts the separatrix");
  cmd->add_flag("--second-round,!--no-second-round", o.quantize.second_round,
                "Drop pairs the first solve could not align and solve again (default: on)");
  cmd->add_option("--threads", o.quantize.threads, "Worker threads for independent components")
      ->default_val(1)
      ->check(whole_number_from(1, 256));
  add_matching_option(cmd, o.quantize.matching,
                      "Perfect matching solver of the exact solves: lemon (the optimum the "
                      "remesh results were measured with), blossom (faster; may pick another "
                      "optimum) or persistent (experimental; slower so far)");
  cmd->add_option("--time-limit", o.quantize.time_limit,
                  "Seconds per solve; then the best quantization found (default: none)")
      ->check(positive_number());
  cmd->add_option("--write-bimdf", o.write_bimdf,
                  "Also write the final round's Bi-MDF model (.bimdf or .json by extension)");
}

CLI::App* add_quantize_command(CLI::App& app, QuantizeCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "quantize",
      "Quantize a QuadWild patch layout: integer subside lengths from an exact Bi-MDF solve");
  add_layout_argument(cmd, o.layout);
  add_quantize_options(cmd, o);
  cmd->add_flag("-v,--verbose", o.verbose, "Per-round sizes, objectives and times");
  add_output_options(cmd, o.out);
  return cmd;
}

quant::QuantizeOptions effective_quantize_options(const QuantizeCommandOptions& o) {
  quant::QuantizeOptions q = o.quantize;
  q.model.simple_targets = !o.half_targets;
  if (o.unalign_weights.size() == 2) {
    q.initial.unalign_weight = o.unalign_weights[0];
    q.resolve.unalign_weight = o.unalign_weights[1];
  }
  return q;
}

QuantizationReport report_quantization(const quant::Layout& layout, const quant::Quantization& q,
                                       const QuantizeCommandOptions& o, double read_s,
                                       double total_s) {
  const quant::QuantizationRound& last = q.final_round();
  double model_s = 0, solve_s = 0;
  for (const auto& r : q.rounds) model_s += r.time_model_s, solve_s += r.time_solve_s;

  int charts = 0;
  for (const quant::Chart& c : layout.charts) charts += !c.empty();
  json j;
  j["layout"] = o.layout;
  j["status"] = std::string(status_name(last.solution.status));
  j["objective"] = last.solution.objective;
  j["edge_length"] = q.edge_length;
  j["estimated_quads"] = std::llround(last.estimated_quads);
  j["charts"] = charts;
  j["subsides"] = layout.subsides.size();
  j["warnings"] = layout.warnings;
  j["energies"] = energies_json(last.energies);
  json rounds = json::array();
  for (const auto& r : q.rounds)
    rounds.push_back({{"objective", r.solution.objective},
                      {"status", std::string(status_name(r.solution.status))},
                      {"nodes", r.model.problem.num_nodes()},
                      {"edges", r.model.problem.num_edges()},
                      {"pairs", r.pairs.size()},
                      {"estimated_quads", std::llround(r.estimated_quads)},
                      {"energies", energies_json(r.energies)},
                      {"time_model_s", r.time_model_s},
                      {"time_solve_s", r.time_solve_s},
                      {"solver", stats_json(r.solution)}});
  j["rounds"] = rounds;
  json subsides = json::array();
  for (size_t s = 0; s < layout.subsides.size(); ++s) {
    const quant::Subside& sub = layout.subsides[s];
    subsides.push_back({{"charts", {sub.charts[0], sub.charts[1]}},
                        {"sides", {sub.sides[0], sub.sides[1]}},
                        {"target", q.targets[s]},
                        {"length", q.lengths()[s]}});
  }
  j["subside_lengths"] = q.lengths();
  j["subside_details"] = subsides;
  json chart_list = json::array();
  for (size_t c = 0; c < layout.charts.size(); ++c) {
    const quant::Chart& chart = layout.charts[c];
    if (chart.empty()) {
      chart_list.push_back(nullptr);
      continue;
    }
    json sides = json::array();
    for (const quant::Side& side : chart.sides) sides.push_back(side.subsides);
    chart_list.push_back(
        {{"valence", chart.valence()},
         {"side_lengths", quant::side_lengths(layout, static_cast<int>(c), q.lengths())},
         {"side_subsides", sides},
         {"irregularity", quant::chart_irregularity(
                              quant::side_lengths(layout, static_cast<int>(c), q.lengths()))}});
  }
  j["chart_details"] = chart_list;
  j["time"] = {
      {"read_s", read_s}, {"model_s", model_s}, {"solve_s", solve_s}, {"total_s", total_s}};

  const quant::Energies& e = last.energies;
  std::ostringstream t;
  t << "layout        " << o.layout << ": " << charts << " charts (" << valence_counts(layout)
    << "), " << layout.subsides.size() << " subsides, " << layout.mesh.num_faces()
    << " triangles\n";
  t << "edge length   " << significant(q.edge_length, 9) << "\n";
  t << "status        " << status_name(last.solution.status) << "\n";
  t << "objective     " << significant(last.solution.objective, 9)
    << (q.rounds.size() > 1 ? " (round 2 of 2)" : "") << "\n";
  t << "energies      isometry " << significant(e.isometry, 9) << ", regularity "
    << significant(e.regularity, 9) << ", alignment " << significant(e.alignment, 9) << "\n";
  t << "charts        " << e.regular_charts << " of " << e.charts << " regular; about "
    << std::llround(last.estimated_quads) << " quads\n";
  if (o.quantize.align)
    t << "alignment     " << e.aligned_pairs << " of " << e.pairs << " pairs aligned"
      << (q.rounds.size() > 1
              ? " (round 2 kept " + std::to_string(q.rounds[1].pairs.size()) + " as constraints)"
              : "")
      << "\n";
  t << "time          " << ms(total_s) << " (read " << ms(read_s) << ", model " << ms(model_s)
    << ", solve " << ms(solve_s) << ")\n";
  if (o.verbose)
    for (size_t r = 0; r < q.rounds.size(); ++r)
      t << "round " << r + 1 << "       " << q.rounds[r].model.problem.num_nodes() << " nodes, "
        << q.rounds[r].model.problem.num_edges() << " edges, " << q.rounds[r].pairs.size()
        << " pairs; objective " << significant(q.rounds[r].solution.objective, 9) << "; model "
        << ms(q.rounds[r].time_model_s) << ", solve " << ms(q.rounds[r].time_solve_s) << "\n";
  return {j, t.str()};
}

void write_quantization_model(const quant::Quantization& q, const QuantizeCommandOptions& o) {
  if (o.write_bimdf.empty()) return;
  const Problem& problem = q.final_round().model.problem;
  const bool as_json =
      o.write_bimdf.size() >= 5 && o.write_bimdf.substr(o.write_bimdf.size() - 5) == ".json";
  write_output_file(o.write_bimdf, as_json ? to_json_problem(problem) : to_bimdf(problem),
                    {o.layout});
}

int run_quantize(const QuantizeCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const quant::Layout layout = quant::read_quadwild_layout(o.layout);
  const double read_s = seconds_since(start);
  const quant::Quantization q = quant::quantize(layout, effective_quantize_options(o));
  write_quantization_model(q, o);
  const QuantizationReport report = report_quantization(layout, q, o, read_s, seconds_since(start));
  for (const std::string& w : layout.warnings) std::cerr << "warning: " << w << "\n";
  deliver(o.out, report.text, report.json.dump(1) + "\n", {o.layout});
  return kOk;
}

}  // namespace bimdf::cli

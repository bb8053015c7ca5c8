// The `bimdf` command-line program: a thin layer that parses options, calls the library and
// prints or writes results. Contract (README, docs/formats.md):
//   --json    print the result JSON on stdout instead of the human summary
//   -o FILE   write the result JSON (or, for convert, the problem) to FILE, atomically
//   exit 0 success, 1 infeasible/unbounded (or a flow that violates the problem),
//        2 invalid input or usage, 3 internal error.
#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bimdf/flow.hpp"
#include "bimdf/generate.hpp"
#include "bimdf/io.hpp"
#include "bimdf/summary.hpp"
#include "bimdf/version.hpp"
#include "memory_setup.hpp"
#include "number_checks.hpp"
#include "output.hpp"
#include "quantize_command.hpp"
#include "remesh_command.hpp"
#include "render_command.hpp"
#include "requantize_command.hpp"
#include "solve_command.hpp"

namespace {

using namespace bimdf;
using namespace bimdf::cli;
using nlohmann::json;

std::string bound_text(int64_t b) {
  return b == kInfinity ? "inf" : b == -kInfinity ? "-inf" : std::to_string(b);
}

std::string format_name(const std::string& text) {
  return detect_problem_format(text) == ProblemFormat::Json ? "json" : "bimdf";
}

json info_json(const std::string& path, const std::string& format, const ProblemSummary& s) {
  json kinds = json::object(), costs = json::object(), terms = json::object();
  for (int k = 0; k < kNumEdgeKinds; ++k)
    kinds[edge_kind_name(static_cast<EdgeKind>(k))] = s.edge_kinds[k];
  for (int k = 0; k < kNumCostKinds; ++k) {
    costs[std::string(cost_kind_name(static_cast<CostKind>(k)))] = s.cost_kinds[k];
    terms[std::string(cost_kind_name(static_cast<CostKind>(k)))] = s.cost_terms[k];
  }
  return {{"file", path},
          {"format", format},
          {"nodes", s.nodes},
          {"edges", s.edges},
          {"nodes_with_demand", s.nodes_with_demand},
          {"total_demand", s.total_demand},
          {"edge_kinds", kinds},
          {"cost_kinds", costs},
          {"cost_terms", terms},
          {"bounds",
           {{"fixed", s.fixed_edges},
            {"finite_upper", s.finite_upper},
            {"positive_lower", s.positive_lower},
            {"negative_lower", s.negative_lower}}},
          {"components", s.components},
          {"largest_component",
           {{"nodes", s.largest_component_nodes}, {"edges", s.largest_component_edges}}},
          {"parity_infeasible_components", s.parity_infeasible_components}};
}

std::string info_text(const std::string& path, const std::string& format, const ProblemSummary& s) {
  std::string t;
  auto line = [&](const std::string& key, const std::string& value) {
    t += key + std::string(key.size() < 14 ? 14 - key.size() : 1, ' ') + value + "\n";
  };
  auto counts = [](const auto& array, int n, auto name_of) {
    std::string r;
    for (int k = 0; k < n; ++k)
      if (array[k])
        r += (r.empty() ? "" : ", ") + std::string(name_of(k)) + " " + std::to_string(array[k]);
    return r.empty() ? std::string("none") : r;
  };
  const std::string demand = shortest_decimal(s.total_demand);
  line("problem", path + " (" + format + ")");
  line("nodes", std::to_string(s.nodes) + " (" + std::to_string(s.nodes_with_demand) +
                    " with non-zero demand, total demand " + demand + ")");
  line("edges", std::to_string(s.edges));
  line("edge kinds", counts(s.edge_kinds, kNumEdgeKinds,
                            [](int k) { return edge_kind_name(static_cast<EdgeKind>(k)); }));
  line("bounds", "fixed " + std::to_string(s.fixed_edges) + ", finite upper " +
                     std::to_string(s.finite_upper) +
                     ", lower > 0: " + std::to_string(s.positive_lower) +
                     ", lower < 0: " + std::to_string(s.negative_lower));
  auto cost_name = [](int k) { return cost_kind_name(static_cast<CostKind>(k)); };
  line("costs", counts(s.cost_kinds, kNumCostKinds, cost_name));
  if (s.cost_kinds[static_cast<int>(CostKind::Sum)])
    line("cost terms", counts(s.cost_terms, kNumCostKinds, cost_name));
  line("components", std::to_string(s.components) +
                         " (largest: " + std::to_string(s.largest_component_nodes) + " nodes, " +
                         std::to_string(s.largest_component_edges) + " edges)");
  if (s.parity_infeasible_components)
    line("infeasible", std::to_string(s.parity_infeasible_components) +
                           " component(s) cannot meet their demands (parity of the total demand)");
  return t;
}

int run_info(const std::string& path, const OutputOptions& out) {
  const std::string text = read_text_file(path);
  const Problem p = parse_problem(text, path);
  const ProblemSummary s = summarize(p);
  deliver(out, info_text(path, format_name(text), s),
          info_json(path, format_name(text), s).dump(2) + "\n", {path});
  return kOk;
}

int run_check(const std::string& problem_path, const std::string& flow_path,
              const OutputOptions& out) {
  const Problem p = read_problem_file(problem_path);
  const std::vector<int64_t> flow = read_flow_file(flow_path);
  if (flow.size() != static_cast<size_t>(p.num_edges()))
    throw InputError(flow_path, "",
                     "the flow has " + std::to_string(flow.size()) + " values but the problem " +
                         problem_path + " has " + std::to_string(p.num_edges()) + " edges");
  const FlowCheck check = check_flow(p, flow);
  constexpr size_t kListed = 20;  // the text lists the first violations; JSON has all of them
  std::string t;
  json bounds = json::array(), conservation = json::array();
  for (const BoundViolation& v : check.bound_violations) {
    bounds.push_back(
        {{"edge", v.edge},
         {"flow", v.flow},
         {"lower", p.lower[v.edge] == -kInfinity ? json("-inf") : json(p.lower[v.edge])},
         {"upper", p.upper[v.edge] == kInfinity ? json("inf") : json(p.upper[v.edge])}});
    if (bounds.size() <= kListed)
      t += "edge " + std::to_string(v.edge) + ": flow " + std::to_string(v.flow) +
           " is outside its bounds [" + bound_text(p.lower[v.edge]) + ", " +
           bound_text(p.upper[v.edge]) + "]\n";
  }
  for (const ConservationViolation& v : check.conservation_violations) {
    // The net flow is exact in 128 bits; it fits a double's range and is printed as such only
    // when it leaves int64.
    const bool fits = v.net_flow >= INT64_MIN && v.net_flow <= INT64_MAX;
    conservation.push_back({{"node", v.node},
                            {"net_flow", fits ? json(static_cast<int64_t>(v.net_flow))
                                              : json(static_cast<double>(v.net_flow))},
                            {"demand", v.demand}});
    if (conservation.size() <= kListed)
      t += "node " + std::to_string(v.node) + ": net flow " +
           conservation.back()["net_flow"].dump() + " differs from its demand " +
           std::to_string(v.demand) + "\n";
  }
  if (bounds.size() > kListed || conservation.size() > kListed)
    t += "(more violations in the JSON result)\n";
  if (check.feasible())
    t += "feasible flow, objective " + shortest_decimal(check.objective) + "\n";
  else
    t += "infeasible flow: " + std::to_string(check.bound_violations.size()) + " bound and " +
         std::to_string(check.conservation_violations.size()) +
         " conservation violations, objective " + shortest_decimal(check.objective) + "\n";
  const json result = {
      {"feasible", check.feasible()},
      {"objective", std::isfinite(check.objective) ? json(check.objective) : json(nullptr)},
      {"bound_violations", bounds},
      {"conservation_violations", conservation}};
  deliver(out, t, result.dump(2) + "\n", {problem_path, flow_path});
  return check.feasible() ? kOk : kNoSolution;
}

int run_convert(const std::string& in_path, const std::string& out_path, std::string to,
                bool libsatsuma) {
  const Problem p = read_problem_file(in_path);
  if (to.empty()) {
    const bool json_ext = out_path.size() >= 5 && out_path.substr(out_path.size() - 5) == ".json";
    to = json_ext ? "json" : "bimdf";
  }
  if (libsatsuma && to != "bimdf") throw cli::UsageError{"--libsatsuma applies to --to bimdf only"};
  std::string text;
  if (to == "json") {
    text = to_json_problem(p);
  } else {
    BimdfWriteOptions options;
    options.libsatsuma_compatible = libsatsuma;
    try {
      text = to_bimdf(p, options);
    } catch (const InputError& e) {
      throw InputError(in_path, "", e.description());  // name the user's file, not the writer
    }
  }
  if (out_path.empty() || out_path == "-")
    std::cout << text;
  else
    cli::write_output_file(out_path, text, {in_path});
  return kOk;
}

int run_generate(const std::string& family, int64_t size, uint64_t seed, const std::string& out,
                 std::string to) {
  const Problem p = generate_problem(family, size, seed);
  if (to.empty()) to = out.size() >= 5 && out.substr(out.size() - 5) == ".json" ? "json" : "bimdf";
  const std::string text = to == "json" ? to_json_problem(p) : to_bimdf(p);
  if (out.empty() || out == "-")
    std::cout << text;
  else
    cli::write_output_file(out, text, {});
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  configure_process_memory(argv);
  // Named, not taken from argv[0], so that usage lines read "Usage: bimdf solve …" however the
  // program was invoked, as the usage errors' help hint does.
  CLI::App app{"bimdf: exact minimum-deviation flows in bidirected graphs (Bi-MDF)", "bimdf"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("bimdf ") + BIMDF_VERSION);
  app.footer(
      "Exit codes: 0 success, 1 infeasible (or a flow that violates the problem), 2 invalid input "
      "or usage, 3 internal error.\n"
      "Problem files: libSatsuma .bimdf text or bimdf JSON, detected by content "
      "(docs/formats.md).");

  OutputOptions out;
  std::string problem, flow, convert_out, to;
  bool libsatsuma = false;

  CLI::App* info = app.add_subcommand(
      "info", "Validate a problem and print its sizes, edge kinds, costs and components");
  info->add_option("PROBLEM", problem, "Problem file (.bimdf or .json)")->required();
  add_output_options(info, out);

  CLI::App* check =
      app.add_subcommand("check", "Verify a flow: bounds, conservation at every node, objective");
  check->add_option("PROBLEM", problem, "Problem file (.bimdf or .json)")->required();
  check
      ->add_option("FLOW", flow,
                   "Flow: a solution JSON, a JSON array, or whitespace-separated integers")
      ->required();
  add_output_options(check, out);

  CLI::App* convert =
      app.add_subcommand("convert", "Convert a problem between the .bimdf and JSON formats");
  convert->add_option("PROBLEM", problem, "Problem file (.bimdf or .json)")->required();
  convert->add_option("-o,--output", convert_out, "Output file (default: stdout)");
  convert
      ->add_option("--to", to, "Output format (default: from the output's extension, else bimdf)")
      ->check(CLI::IsMember({"bimdf", "json"}));
  convert->add_flag("--libsatsuma", libsatsuma,
                    "Write only what libSatsuma can read (2147483647 as infinity, its cost kinds); "
                    "fail otherwise");

  std::string family, generate_out, generate_format;
  int64_t size = 10000;
  uint64_t seed = 1;
  CLI::App* generate = app.add_subcommand(
      "generate", "Write a deterministic random or QuadWild-like benchmark instance");
  generate->add_option("FAMILY", family, "random or quadwild")
      ->required()
      ->check(CLI::IsMember(generator_family_names()));
  generate->add_option("--size", size, "Approximate number of edges")
      ->default_val(10000)
      ->check(whole_number_from(1, 100000000));
  generate->add_option("--seed", seed, "Random seed")->default_val(1);
  generate->add_option("-o,--output", generate_out, "Output file (default: stdout)");
  generate->add_option("--to", generate_format, "bimdf or json (default: from the extension)")
      ->check(CLI::IsMember({"bimdf", "json"}));

  SolveCommandOptions solve_options;
  CLI::App* solve = add_solve_command(app, solve_options);
  QuantizeCommandOptions quantize_options;
  CLI::App* quantize = add_quantize_command(app, quantize_options);
  RemeshCommandOptions remesh_options;
  CLI::App* remesh = add_remesh_command(app, remesh_options);
  RemeshCommandOptions tessellate_options;
  CLI::App* tessellate = add_tessellate_command(app, tessellate_options);
  MetricsCommandOptions metrics_options;
  CLI::App* metrics = add_metrics_command(app, metrics_options);
  RenderCommandOptions render_options;
  CLI::App* render = add_render_command(app, render_options);
  RequantizeCommandOptions requantize_options;
  CLI::App* requantize = add_requantize_command(app, requantize_options);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive as "errors" of exit code 0; CLI11 prints them.
    if (e.get_exit_code() == 0) return app.exit(e) == 0 ? kOk : kBadInput;
    // Usage errors read like every other error of the program, and name the help that applies:
    // the subcommand's, when one was chosen before the error.
    std::string help = app.get_name(), message = e.what();
    if (const std::vector<CLI::App*> chosen = app.get_subcommands(); !chosen.empty()) {
      help += " " + chosen.front()->get_name();
    } else if (argc > 1) {
      // CLI11 reports only "A subcommand is required" when the first word is none of them.
      const std::string first = argv[1];
      message = first.starts_with("-") ? "unknown option '" + first + "' (expected a subcommand)"
                                       : "unknown subcommand '" + first + "'";
    }
    std::cerr << "error: " << message << "\nRun '" << help << " --help' for the options.\n";
    return kBadInput;
  }

  try {
    if (*info) return run_info(problem, out);
    if (*check) return run_check(problem, flow, out);
    if (*convert) return run_convert(problem, convert_out, to, libsatsuma);
    if (*solve) return run_solve(solve_options);
    if (*quantize) return run_quantize(quantize_options);
    if (*remesh) return run_remesh(remesh_options);
    if (*tessellate) return run_tessellate(tessellate_options);
    if (*metrics) return run_metrics(metrics_options);
    if (*render) return run_render(render_options);
    if (*requantize) return run_requantize(requantize_options);
    if (*generate) return run_generate(family, size, seed, generate_out, generate_format);
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kBadInput;
  } catch (const cli::UsageError& e) {
    std::cerr << "error: " << e.message << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return kInternal;
  }
  return kInternal;
}

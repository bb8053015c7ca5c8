// bimdf_bench: the benchmark runner (docs/benchmarks.md). Runs `bimdf solve --json` — exact and
// approximate — on every instance of a folder and on a generated scaling series, each run in its
// own process so that peak memory is per run; takes the median of repeated runs; optionally
// solves the same problems as MILPs with CBC as the generic-solver baseline; writes a CSV and
// the results section of a Markdown file (machine, compiler, commit).
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bench_util.hpp"
#include "bimdf/generate.hpp"
#include "bimdf/io.hpp"
#include "generality_bench.hpp"
#include "half_arc_bench.hpp"
#include "layout_bench.hpp"
#include "markdown_table.hpp"
#include "milp_model.hpp"
#include "remesh_bench.hpp"
#include "requantize_bench.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace bimdf::bench;

struct Instance {
  std::string name, path, group;  // group: "shared" or "scaling"
  int nodes = 0, edges = 0;
  double reference = NAN;  // a known optimum
  // The reference implementation's times from the instances' README table (NAN if absent).
  double libsatsuma_approx_ms = NAN, libsatsuma_exact_ms = NAN;
};

// The README of the shared instances has a table "| file | nodes | edges | optimum | approx
// cost | approx ms | exact ms |"; returns file → (approx ms, exact ms).
std::map<std::string, std::pair<double, double>> read_libsatsuma_times(const fs::path& readme) {
  std::map<std::string, std::pair<double, double>> times;
  std::ifstream in(readme);
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> cells = markdown_cells(line);
    // A leading empty cell comes from the row's first '|'.
    if (cells.size() < 8 || cells[1].size() < 7 || !cells[1].ends_with(".bimdf")) continue;
    try {
      times[cells[1]] = {std::stod(cells[6]), std::stod(cells[7])};
    } catch (const std::exception&) {
    }
  }
  return times;
}

struct Row {
  Instance instance;
  std::string mode, status;
  int runs = 0;
  double objective = NAN, read_s = 0, solve_s = 0, peak_mb = 0;
  json stats;
};

Row measure(const std::string& cli, const Instance& in, bool exact, int repeats,
            double time_limit) {
  Row row;
  row.instance = in;
  row.mode = exact ? "exact" : "approx";
  std::vector<std::string> args{"solve", "--json"};
  if (!exact) args.push_back("--approx");
  if (exact && time_limit > 0)
    args.insert(args.end(), {"--time-limit", std::to_string(time_limit)});
  args.push_back(in.path);
  std::vector<double> solve, read;
  std::vector<Run> runs;
  for (int k = 0; k < repeats; ++k) {
    runs.push_back(run_cli(cli, args));
    const json& st = runs.back().solution["stats"];
    solve.push_back(st["time_solve_s"].get<double>());
    read.push_back(st["time_read_s"].get<double>());
    row.peak_mb = std::max(row.peak_mb, st.value("peak_memory_mb", runs.back().peak_rss_mb));
    // Medians of at least 5 for runs under a second; longer ones 3 times at most.
    if (k == 0 && solve.back() > 1.0) repeats = std::min(repeats, 3);
  }
  row.runs = static_cast<int>(solve.size());
  row.solve_s = median(solve);
  row.read_s = median(read);
  // The stats of the run closest to the median.
  size_t best = 0;
  for (size_t k = 0; k < solve.size(); ++k)
    if (std::fabs(solve[k] - row.solve_s) < std::fabs(solve[best] - row.solve_s)) best = k;
  const json& sol = runs[best].solution;
  row.status = sol["status"];
  if (sol["objective"].is_number()) row.objective = sol["objective"];
  row.stats = sol["stats"];
  return row;
}

double stat(const json& s, const char* key) { return s.contains(key) ? s[key].get<double>() : 0; }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bimdf_bench: benchmark the exact and approximate solvers"};
  std::string instances_dir, csv_path, md_path, cli = BIMDF_CLI_PATH, family = "quadwild";
  std::vector<int64_t> scaling{1000, 10000, 100000};
  int repeats = 5;
  double time_limit = 600, milp_seconds = 0;
  int milp_max_edges = 2500;
  int64_t milp_radius = 8;
  app.add_option("--instances", instances_dir, "Folder of .bimdf instances (with expected.tsv)");
  app.add_option("--scaling", scaling, "Sizes (edges) of the generated scaling series")
      ->delimiter(',');
  app.add_option("--family", family, "Generator family of the scaling series");
  app.add_option("--repeats", repeats, "Runs per instance and mode (median; 3 for runs > 1 s)")
      ->check(CLI::Range(1, 100));
  app.add_option("--time-limit", time_limit, "Seconds per exact solve (then: best flow)");
  app.add_option("--milp-seconds", milp_seconds,
                 "CBC baseline time limit per instance (0: no baseline)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // scripts/bench.sh sets a default
  app.add_option("--milp-max-edges", milp_max_edges, "Largest instance given to the baseline");
  app.add_option("--milp-radius", milp_radius,
                 "Baseline flows limited to each cost's minimizer ± this (keeps the MILP small)");
  app.add_option("--csv", csv_path, "CSV output");
  app.add_option("--markdown", md_path,
                 "Markdown file whose section between <!-- bench:begin --> and "
                 "<!-- bench:end --> is replaced by the results");
  app.add_option("--cli", cli, "The bimdf program to run");
  std::string layouts_dir;
  bool only_layouts = false;
  app.add_flag("--only-layouts", only_layouts,
               "Run just the layout benchmark (no instances, no scaling series)");
  app.add_option("--layouts", layouts_dir,
                 "Folder of QuadWild layouts (with expected.tsv): benchmark `bimdf quantize` and "
                 "`bimdf remesh`, replacing the <!-- quantize:begin/end --> and "
                 "<!-- remesh:begin/end --> sections of the Markdown file");
  bool only_requantize = false;
  app.add_flag("--only-requantize", only_requantize,
               "Run just the requantize benchmark on the --layouts folder (replaces the "
               "<!-- requantize:begin/end --> section)");
  bool only_half_arc = false;
  app.add_flag("--only-half-arc", only_half_arc,
               "Run just the half-arc benchmark on the --layouts folder: `requantize --coarse` at "
               "10°-45° with --half-arc off / exact / bounded (replaces the "
               "<!-- half-arc:begin/end --> section)");
  bool only_generality = false;
  app.add_flag("--only-generality", only_generality,
               "Run just the generality benchmark: matchings, directed min-cost flows and "
               "b-matchings as Bi-MDF against LEMON's dedicated algorithms (replaces the "
               "<!-- generality:begin/end --> section)");
  CLI11_PARSE(app, argc, argv);
  // Prints a section and puts it into the Markdown file; false if the file lacks its markers.
  const auto write_section = [&](const std::string& name, const std::string& body) {
    std::cout << "\n" << body;
    if (md_path.empty() || replace_section(md_path, name, body)) return true;
    std::cerr << md_path << ": no <!-- " << name << ":begin --> ... <!-- " << name
              << ":end --> section\n";
    return false;
  };
  if (only_requantize) {
    if (layouts_dir.empty()) {
      std::cerr << "--only-requantize needs --layouts\n";
      return 2;
    }
    return write_section("requantize", benchmark_requantize(cli, layouts_dir, repeats)) ? 0 : 2;
  }
  if (only_half_arc) {
    if (layouts_dir.empty()) {
      std::cerr << "--only-half-arc needs --layouts\n";
      return 2;
    }
    return write_section("half-arc", benchmark_half_arc(cli, layouts_dir, repeats)) ? 0 : 2;
  }
  if (only_generality) return write_section("generality", benchmark_generality(repeats)) ? 0 : 2;
  if (only_layouts) {
    instances_dir.clear();
    scaling.clear();
  }

  std::vector<Instance> instances;
  if (!instances_dir.empty()) {
    std::map<std::string, double> optimum;
    std::ifstream tsv(fs::path(instances_dir) / "expected.tsv");
    std::string line;
    std::getline(tsv, line);
    while (std::getline(tsv, line)) {
      std::istringstream row(line);
      std::string file;
      int n, m;
      double opt;
      if (row >> file >> n >> m >> opt) optimum[file] = opt;
    }
    const auto libsatsuma = read_libsatsuma_times(fs::path(instances_dir) / "README.md");
    for (const auto& e : fs::directory_iterator(instances_dir))
      if (e.path().extension() == ".bimdf") {
        Instance in{e.path().filename().string(), e.path().string(), "shared"};
        if (optimum.count(in.name)) in.reference = optimum[in.name];
        if (auto it = libsatsuma.find(in.name); it != libsatsuma.end())
          std::tie(in.libsatsuma_approx_ms, in.libsatsuma_exact_ms) = it->second;
        instances.push_back(in);
      }
  }
  const fs::path scratch = fs::temp_directory_path() / ("bimdf_bench_" + std::to_string(getpid()));
  fs::create_directories(scratch);
  for (int64_t size : scaling) {
    const std::string name = family + "-" + std::to_string(size) + ".bimdf";
    std::ofstream((scratch / name).string())
        << bimdf::to_bimdf(bimdf::generate_problem(family, size, 1));
    instances.push_back({name, (scratch / name).string(), "scaling"});
  }
  for (Instance& in : instances) {
    const bimdf::Problem p = bimdf::read_problem_file(in.path);
    in.nodes = p.num_nodes();
    in.edges = p.num_edges();
  }
  std::stable_sort(instances.begin(), instances.end(), [](const Instance& a, const Instance& b) {
    return a.group != b.group ? a.group == "shared" : a.edges < b.edges;
  });

  std::vector<Row> rows;
  std::map<std::string, std::pair<std::string, double>> milp;  // instance → status, objective/time
  std::map<std::string, double> milp_time;
  for (const Instance& in : instances) {
    for (bool exact : {false, true}) {
      rows.push_back(measure(cli, in, exact, repeats, time_limit));
      const Row& r = rows.back();
      std::cerr << r.mode << " " << in.name << ": " << r.status << " " << fmt(r.objective, 9)
                << " in " << fmt(r.solve_s * 1e3) << " ms (" << r.runs << " runs)\n";
    }
    if (milp_seconds > 0 && in.edges <= milp_max_edges) {
      const auto t = std::chrono::steady_clock::now();
      const bimdf::testing::MilpResult m = bimdf::testing::solve_milp(
          bimdf::read_problem_file(in.path), -100000, 100000, milp_seconds, milp_radius);
      milp_time[in.name] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
      milp[in.name] = {!m.feasible ? (m.proven ? "infeasible" : "none")
                       : m.proven  ? "optimal"
                                   : "time limit",
                       m.feasible ? m.objective : NAN};
      std::cerr << "milp " << in.name << ": " << milp[in.name].first << "\n";
    }
  }
  fs::remove_all(scratch);

  if (!csv_path.empty()) {
    std::ofstream csv(csv_path);
    csv << "instance,group,nodes,edges,components,mode,status,objective,reference,runs,"
           "read_s,solve_s,simplify_s,lp_guess_s,approximation_s,refine_build_s,pruning_s,"
           "matching_s,lower_bound_s,rounds,matchings,peak_rss_mb,milp_status,milp_objective,"
           "milp_s\n";
    for (const Row& r : rows) {
      const json& s = r.stats;
      const double approx_s =
          stat(s, "time_parity_s") + stat(s, "time_linearize_s") + stat(s, "time_min_cost_flow_s");
      const bool has_milp = milp.count(r.instance.name) && r.mode == "exact";
      csv << r.instance.name << "," << r.instance.group << "," << r.instance.nodes << ","
          << r.instance.edges << "," << s.value("components", 0) << "," << r.mode << "," << r.status
          << "," << fmt(r.objective, 12) << "," << fmt(r.instance.reference, 9) << "," << r.runs
          << "," << r.read_s << "," << r.solve_s << "," << stat(s, "time_simplify_s") << ","
          << stat(s, "time_lp_guess_s") << "," << approx_s << "," << stat(s, "time_refine_build_s")
          << "," << stat(s, "time_pruning_s") << "," << stat(s, "time_matching_s") << ","
          << stat(s, "time_lower_bound_s") << "," << s.value("refinement_rounds", 0) << ","
          << s.value("matchings_solved", 0) << "," << r.peak_mb << ","
          << (has_milp ? milp[r.instance.name].first : "") << ","
          << (has_milp ? fmt(milp[r.instance.name].second, 9) : "") << ","
          << (has_milp ? fmt(milp_time[r.instance.name]) : "") << "\n";
    }
  }

  // Markdown: environment, per-instance table, totals, scaling fit.
  std::ostringstream md;
  md << "Generated by `bimdf_bench` on " << shell("date -u +%Y-%m-%d") << ", commit `"
     << shell("git -C " + std::string(fs::path(argv[0]).parent_path()) +
              " rev-parse --short HEAD 2>/dev/null || echo unknown")
     << "`. Machine: " << shell("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'")
     << ", " << shell("nproc") << " cores, "
     << shell("awk '/MemTotal/ {printf \"%.0f GiB\", $2/1048576}' /proc/meminfo") << "; compiler "
     << __VERSION__ << ". Times: median of " << repeats
     << " runs (3 for runs over 1 s), solve only (parsing separate); memory: peak resident set "
        "of the process.\n\n";
  md << "| instance | nodes | edges | approx ms | approx gap | exact ms | rounds | matchings "
        "| LP guess ms | pruning ms | matching ms | peak MiB | status | objective | reference | "
        "libSatsuma exact ms |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  double libsatsuma_exact = 0, libsatsuma_approx = 0;
  int above_1000 = 0, within_fifth = 0;
  // Stages of the exact solves summed over the shared instances: the profile of the document.
  const std::vector<std::pair<std::string, std::string>> stages{
      {"simplify", "time_simplify_s"},
      {"LP guess", "time_lp_guess_s"},
      {"parity", "time_parity_s"},
      {"linearize", "time_linearize_s"},
      {"cover min-cost flow", "time_min_cost_flow_s"},
      {"refinement build", "time_refine_build_s"},
      {"pruning LP", "time_pruning_s"},
      {"matching", "time_matching_s"},
      {"lower bound", "time_lower_bound_s"}};
  std::vector<double> stage_total(stages.size(), 0.0);
  double total_exact = 0, total_approx = 0;
  std::vector<double> gaps;
  std::vector<std::pair<double, double>> scaling_points;
  for (size_t i = 0; i + 1 < rows.size(); i += 2) {
    const Row &a = rows[i], &e = rows[i + 1];
    const double gap = (a.objective - e.objective) / std::max(std::fabs(e.objective), 1e-12);
    if (e.instance.group == "shared") {
      total_exact += e.solve_s;
      total_approx += a.solve_s;
      gaps.push_back(gap);
      for (size_t k = 0; k < stages.size(); ++k)
        stage_total[k] += stat(e.stats, stages[k].second.c_str());
      libsatsuma_exact += e.instance.libsatsuma_exact_ms / 1e3;
      libsatsuma_approx += e.instance.libsatsuma_approx_ms / 1e3;
      if (e.instance.edges > 1000 && !std::isnan(e.instance.libsatsuma_exact_ms)) {
        ++above_1000;
        within_fifth += e.solve_s * 1e3 <= e.instance.libsatsuma_exact_ms / 5;
      }
    } else {
      scaling_points.push_back({std::log(e.instance.edges), std::log(e.solve_s)});
    }
    md << "| " << e.instance.name << " | " << e.instance.nodes << " | " << e.instance.edges << " | "
       << fmt(a.solve_s * 1e3) << " | " << fmt(100 * gap, 1) << "% | " << fmt(e.solve_s * 1e3)
       << " | " << e.stats.value("refinement_rounds", 0) << " | "
       << e.stats.value("matchings_solved", 0) << " | "
       << fmt(stat(e.stats, "time_lp_guess_s") * 1e3) << " | "
       << fmt(stat(e.stats, "time_pruning_s") * 1e3) << " | "
       << fmt(stat(e.stats, "time_matching_s") * 1e3) << " | " << fmt(e.peak_mb, 0) << " | "
       << e.status << " | " << fmt(e.objective, 9) << " | " << fmt(e.instance.reference, 9) << " | "
       << fmt(e.instance.libsatsuma_exact_ms) << " |\n";
  }
  if (!gaps.empty()) {
    std::sort(gaps.begin(), gaps.end());
    md << "\nShared instances: exact total " << fmt(total_exact, 3) << " s, approximation total "
       << fmt(total_approx, 3) << " s, approximation gap median " << fmt(100 * median(gaps), 1)
       << "%, 95th percentile " << fmt(100 * gaps[(gaps.size() * 95) / 100], 1) << "%, max "
       << fmt(100 * gaps.back(), 1) << "%. libSatsuma (README of the instances): exact total "
       << fmt(libsatsuma_exact, 3) << " s, approximation total " << fmt(libsatsuma_approx, 3)
       << " s. Instances above 1,000 edges solved exactly within a fifth of libSatsuma's time: "
       << within_fifth << " of " << above_1000 << ".\n";
    md << "Exact solves by stage, summed over the shared instances (one run each, the median "
          "run):";
    for (size_t k = 0; k < stages.size(); ++k)
      md << (k ? ", " : " ") << stages[k].first << " " << fmt(stage_total[k], 3) << " s";
    md << ".\n";
  }
  if (scaling_points.size() >= 2) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(scaling_points.size());
    for (auto [x, y] : scaling_points) sx += x, sy += y, sxx += x * x, sxy += x * y;
    md << "Scaling series (" << family << "): exact time grows as edges^"
       << fmt((n * sxy - sx * sy) / (n * sxx - sx * sx), 2) << " (least-squares fit).\n";
  }
  if (!milp.empty()) {
    md << "\nMILP baseline (CBC, " << milp_seconds << " s limit; costs exact at integers; "
       << "flows on curved costs limited to the cost's minimizer ± " << milp_radius
       << ", so CBC solves a restriction and its optimum can only be higher):\n\n"
       << "| instance | CBC status | CBC objective | CBC s | bimdf exact ms "
          "|\n|---|---|---|---|---|\n";
    for (size_t i = 1; i < rows.size(); i += 2)
      if (milp.count(rows[i].instance.name))
        md << "| " << rows[i].instance.name << " | " << milp[rows[i].instance.name].first << " | "
           << fmt(milp[rows[i].instance.name].second, 9) << " | "
           << fmt(milp_time[rows[i].instance.name], 1) << " | " << fmt(rows[i].solve_s * 1e3)
           << " |\n";
  }
  if (!rows.empty()) {
    if (!write_section("bench", md.str())) return 2;
    if (!write_section("generality", benchmark_generality(repeats))) return 2;
  }
  if (!layouts_dir.empty()) {
    if (!write_section("quantize", benchmark_layouts(cli, layouts_dir, repeats))) return 2;
    if (!write_section("remesh", benchmark_remesh(cli, layouts_dir, repeats))) return 2;
  }
  return 0;
}

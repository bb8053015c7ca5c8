// bimdf_requantize_floor: how few quads the separation constraints of `bimdf requantize` allow,
// and whether Algorithm 2's greedy min-one bounds (paper §4.2.3) cost anything there.
//
// For each quad mesh: trace its T-mesh at the density asked for (--scale F: 1/F output edges
// per input edge), then solve with CBC, to proven optimality, the integer program
//     min Σ_a x_a   over arc lengths x_a ∈ {0, 1, …}
//     s.t. opposite sides of every patch have equal sums, and either
//          (greedy) Algorithm 2's bounds: x_a ≥ 1 for its arcs, Σ side ≥ 1 for its sides, or
//          (exact)  Σ over every non-zero path ≥ 1,
// and report each solution's quads (Σ over patches of width × height) against the quads the
// density asks for (the targets' area, as requantize's calibration aims at). The total length
// stands in for the quad count, which is quadratic in the lengths; the fewer the lengths, the
// fewer the quads, and both programs are measured the same way. The requantize pipeline's
// repairs (tmesh/separation_repair.hpp) only add bounds, so they can only raise these floors.
//
// Usage: bimdf_requantize_floor [--scale F] [--time-limit S] QUAD.obj...
// Prints a Markdown table on stdout; exit 2 on bad arguments, 1 if a mesh failed (named on
// stderr, the others still measured).
#include <Cbc_C_Interface.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "bimdf/tmesh/quantize.hpp"

namespace {

using bimdf::tmesh::MinOneConstraints;
using bimdf::tmesh::TMesh;

struct Floor {
  std::vector<int64_t> length;  // empty: CBC found no solution in time
  double total = 0;             // Σ x_a
  bool proven = false;          // CBC proved it optimal
  double seconds = 0;
};

// One row Σ coefficient · x ≥ / = rhs over the arcs of `half_arcs` (each arc once per entry).
void add_row(Cbc_Model* m, const std::vector<int>& half_arcs, double coefficient, char sense,
             double rhs, std::vector<int>& cols, std::vector<double>& coefs) {
  for (int h : half_arcs) cols.push_back(TMesh::arc_of(h)), coefs.push_back(coefficient);
  if (sense == 0) return;  // more terms follow
  Cbc_addRow(m, "", static_cast<int>(cols.size()), cols.data(), coefs.data(), sense, rhs);
  cols.clear(), coefs.clear();
}

using CbcModel = std::unique_ptr<Cbc_Model, void (*)(Cbc_Model*)>;

// A silent CBC model, solved to proven optimality within `time_limit`, with `columns` integer
// lengths of objective weight `weight` each, bounded by the input's edge count (an arc longer
// than all the input's edges together is never part of a floor).
CbcModel new_length_model(const TMesh& t, int columns, double weight, double time_limit) {
  CbcModel model(Cbc_newModel(), Cbc_deleteModel);
  Cbc_Model* m = model.get();
  Cbc_setLogLevel(m, 0);
  Cbc_setMaximumSeconds(m, time_limit);
  Cbc_setAllowableGap(m, 0.0);
  int64_t cap = 1;
  for (const auto& chain : t.arc_chain) cap += static_cast<int64_t>(chain.size());
  for (int c = 0; c < columns; ++c)
    Cbc_addCol(m, "", 0, static_cast<double>(cap), weight, 1, 0, nullptr, nullptr);
  return model;
}

// The program above; `greedy` null: the exact path constraints.
Floor solve_floor(const TMesh& t, const MinOneConstraints* greedy, double time_limit) {
  const auto start = std::chrono::steady_clock::now();
  const CbcModel model = new_length_model(t, t.num_arcs(), 1, time_limit);
  Cbc_Model* m = model.get();
  std::vector<int> cols;
  std::vector<double> coefs;
  for (const auto& sides : t.patch_sides)
    for (int k = 0; k < 2; ++k) {
      add_row(m, sides[k], 1, 0, 0, cols, coefs);
      add_row(m, sides[k + 2], -1, 'E', 0, cols, coefs);
    }
  if (greedy) {
    for (int a : greedy->arcs) add_row(m, {2 * a}, 1, 'G', 1, cols, coefs);
    for (const auto& s : greedy->sides)
      add_row(m, t.patch_sides[s[0]][s[1]], 1, 'G', 1, cols, coefs);
  } else {
    for (const std::vector<int>& path : t.nonzero_paths) {
      // A path may run along an arc twice (once each way): one coefficient per arc.
      std::vector<int> arcs;
      for (int h : path) arcs.push_back(2 * TMesh::arc_of(h));
      std::sort(arcs.begin(), arcs.end());
      arcs.erase(std::unique(arcs.begin(), arcs.end()), arcs.end());
      add_row(m, arcs, 1, 'G', 1, cols, coefs);
    }
  }
  Cbc_solve(m);
  Floor f;
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  f.proven = Cbc_isProvenOptimal(m);
  if (Cbc_numberSavedSolutions(m) == 0 && !f.proven) return f;
  const double* x = Cbc_getColSolution(m);
  for (int a = 0; a < t.num_arcs(); ++a) f.length.push_back(std::llround(x[a]));
  for (int64_t l : f.length) f.total += static_cast<double>(l);
  return f;
}

// The half-arc relaxation of the exact program (paper §4.3): one length per half-arc, opposite
// half-arcs equal unless their arc lies on a non-zero path, each patch's opposite sides equal,
// and along each path the lengths on either side summing equally (the path's total ≥ 1). Only
// a lower bound on what half-arc quantization reaches: overlapping paths are not merged first.
// Returns the quads (Σ over patches of width × height) of its optimum, or −1 without one.
double half_arc_floor(const TMesh& t, double time_limit, bool* proven, double* seconds) {
  const auto start = std::chrono::steady_clock::now();
  const CbcModel model = new_length_model(t, t.num_half_arcs(), 0.5, time_limit);
  Cbc_Model* m = model.get();
  std::vector<char> on_side(t.num_half_arcs(), 0), on_path(t.num_arcs(), 0);
  for (const auto& sides : t.patch_sides)
    for (const auto& side : sides)
      for (int h : side) on_side[h] = 1;
  for (const auto& path : t.nonzero_paths)
    for (int h : path) on_path[TMesh::arc_of(h)] = 1;
  std::vector<int> cols;
  std::vector<double> coefs;
  auto row = [&](char sense, double rhs) {
    Cbc_addRow(m, "", static_cast<int>(cols.size()), cols.data(), coefs.data(), sense, rhs);
    cols.clear(), coefs.clear();
  };
  for (int a = 0; a < t.num_arcs(); ++a)
    if (!on_path[a] || !on_side[2 * a] || !on_side[2 * a + 1]) {
      cols = {2 * a, 2 * a + 1}, coefs = {1, -1};
      row('E', 0);
    }
  for (const auto& sides : t.patch_sides)
    for (int k = 0; k < 2; ++k) {
      for (int h : sides[k]) cols.push_back(h), coefs.push_back(1);
      for (int h : sides[k + 2]) cols.push_back(h), coefs.push_back(-1);
      row('E', 0);
    }
  for (const std::vector<int>& path : t.nonzero_paths) {
    std::vector<double> coef(t.num_half_arcs(), 0);
    for (int h : path) coef[h] += 1, coef[TMesh::opposite(h)] -= 1;
    for (int h : path)
      for (int g : {h, TMesh::opposite(h)})
        if (coef[g] != 0) cols.push_back(g), coefs.push_back(coef[g]), coef[g] = 0;
    if (!cols.empty()) row('E', 0);
    for (int h : path) cols.push_back(h), coefs.push_back(1);
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    coefs.assign(cols.size(), 1);
    row('G', 1);
  }
  Cbc_solve(m);
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  *proven = Cbc_isProvenOptimal(m);
  if (Cbc_numberSavedSolutions(m) == 0 && !*proven) return -1;
  const double* x = Cbc_getColSolution(m);
  double quads = 0;
  for (const auto& sides : t.patch_sides) {
    double w = 0, h = 0;
    for (int g : sides[0]) w += std::llround(x[g]);
    for (int g : sides[1]) h += std::llround(x[g]);
    quads += w * h;
  }
  return quads;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "The fewest quads the separation constraints of requantize allow: Algorithm 2's "
      "greedy bounds against the exact non-zero path constraints (CBC, min Σ length)"};
  double scale = 2, time_limit = 600;
  std::vector<std::string> meshes;
  app.add_option("--scale", scale, "Output edge length in input edges")
      ->check(CLI::PositiveNumber)
      ->default_val(2);
  app.add_option("--time-limit", time_limit, "Seconds CBC may take per program")
      ->check(CLI::PositiveNumber)
      ->default_val(600);
  app.add_option("meshes", meshes, "All-quad OBJ meshes")->required()->check(CLI::ExistingFile);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;  // bad arguments: exit 2, as bimdf does
  }

  std::printf(
      "| mesh | arcs | non-zero paths | greedy bounds | target quads | greedy: Σ length | quads "
      "| × target | exact: Σ length | quads | × target | half-arc: quads | × target | CBC time "
      "(greedy / exact / half-arc) |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int status = 0;
  for (const std::string& path : meshes) {
    try {
      bimdf::tmesh::TraceOptions trace;
      trace.density = 1 / scale;
      const bimdf::tmesh::TracedTMesh traced =
          bimdf::tmesh::trace_tmesh(bimdf::read_obj_quads(path), trace, path);
      const TMesh& t = traced.tmesh;
      const bimdf::tmesh::TMeshIncidence incidence = bimdf::tmesh::validate_tmesh(t, path);
      const MinOneConstraints greedy = bimdf::tmesh::greedy_min_one_constraints(t, incidence);
      const double target = bimdf::tmesh::target_quads(t);
      std::string row =
          "| " + path.substr(path.find_last_of('/') + 1) + " | " + std::to_string(t.num_arcs()) +
          " | " + std::to_string(t.nonzero_paths.size()) + " | " + std::to_string(greedy.size()) +
          " | " + std::to_string(std::llround(target));
      std::string times;
      for (const MinOneConstraints* bounds :
           {&greedy, static_cast<const MinOneConstraints*>(nullptr)}) {
        const Floor f = solve_floor(t, bounds, time_limit);
        const std::string error =
            f.length.empty() ? "no solution" : bimdf::tmesh::check_quantization(t, f.length);
        if (!error.empty()) throw std::runtime_error("the floor failed its check: " + error);
        const double quads = bimdf::tmesh::quantized_quads(t, f.length);
        char cell[160];
        std::snprintf(cell, sizeof cell, " | %.0f%s | %.0f | %.2f", f.total,
                      f.proven ? "" : " (not proven)", quads, quads / target);
        row += cell;
        std::snprintf(cell, sizeof cell, "%s%.1f s", times.empty() ? "" : " / ", f.seconds);
        times += cell;
      }
      bool proven = false;
      double seconds = 0;
      const double half = half_arc_floor(t, time_limit, &proven, &seconds);
      char cell[160];
      std::snprintf(cell, sizeof cell, " | %.0f%s | %.2f", half, proven ? "" : " (not proven)",
                    half / target);
      row += cell;
      std::snprintf(cell, sizeof cell, " / %.1f s", seconds);
      times += cell;
      std::printf("%s | %s |\n", row.c_str(), times.c_str());
      std::fflush(stdout);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s: %s\n", path.c_str(), e.what());
      status = 1;
    }
  }
  return status;
}

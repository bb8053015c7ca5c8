// Helpers shared by the benchmark programs (bench_util.hpp).
#include "bench_util.hpp"

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace bimdf::bench {

// Runs the CLI with `args`, returns its JSON output and the child's peak resident memory.
Run run_cli(const std::string& cli, const std::vector<std::string>& args) {
  int out[2];
  if (pipe(out) != 0) throw std::runtime_error("pipe failed");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  std::vector<char*> argv{const_cast<char*>(cli.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid;
  if (posix_spawn(&pid, cli.c_str(), &actions, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot run " + cli);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  std::string text;
  char buf[65536];
  for (ssize_t n; (n = read(out[0], buf, sizeof buf)) > 0;) text.append(buf, n);
  close(out[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  if (!WIFEXITED(status) || WEXITSTATUS(status) > 1)
    throw std::runtime_error(cli + " failed on " + args.back());
  return {nlohmann::json::parse(text), usage.ru_maxrss / 1024.0};
}

void for_each_remeshed_layout(
    const std::string& cli, const std::string& dir,
    const std::function<void(const std::string&, const std::string&, const std::string&)>& visit) {
  namespace fs = std::filesystem;
  const std::vector<LayoutReference> refs = read_layout_references(dir);
  const fs::path scratch =
      fs::temp_directory_path() / ("bimdf_bench_" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  const std::string out = (scratch / "out.obj").string();
  for (const LayoutReference& ref : refs) {
    const std::string obj = (fs::path(dir) / ref.mesh / (ref.mesh + ".obj")).string();
    std::string in = (scratch / (ref.mesh + ".quads.obj")).string();
    try {
      run_cli(cli, {"remesh", "--json", "-o", in, obj});
    } catch (const std::exception&) {
      in.clear();
    }
    visit(ref.mesh, in, out);
  }
  fs::remove_all(scratch);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

MedianRun median_run(const std::string& cli, const std::vector<std::string>& args, int repeats) {
  std::vector<double> times;
  std::vector<nlohmann::json> outputs;
  for (int k = 0; k < repeats; ++k) {
    outputs.push_back(run_cli(cli, args).solution);
    times.push_back(outputs.back()["time"]["total_s"].get<double>());
    if (k == 0 && times.back() > 1.0) repeats = std::min(repeats, 3);
  }
  const double mid = median(times);
  size_t best = 0;
  for (size_t k = 0; k < times.size(); ++k)
    if (std::fabs(times[k] - mid) < std::fabs(times[best] - mid)) best = k;
  return {outputs[best], mid};
}

std::vector<LayoutReference> read_layout_references(const std::string& dir) {
  std::vector<LayoutReference> refs;
  std::ifstream tsv(std::filesystem::path(dir) / "expected.tsv");
  std::string line;
  std::getline(tsv, line);  // header
  while (std::getline(tsv, line)) {
    std::istringstream row(line);
    LayoutReference r;
    int patches;
    if (row >> r.mesh >> patches >> r.noalign_opt >> r.align_opt >> r.noalign_quads >>
        r.align_quads)
      refs.push_back(r);
  }
  return refs;
}

std::string fmt(double v, int precision) {
  if (std::isnan(v)) return "–";
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(precision);
  s << v;
  return s.str();
}

std::string shell(const std::string& cmd) {
  std::string out;
  if (FILE* f = popen(cmd.c_str(), "r")) {
    char buf[512];
    while (fgets(buf, sizeof buf, f)) out += buf;
    pclose(f);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

bool replace_section(const std::string& path, const std::string& name, const std::string& body) {
  std::ifstream in(path);
  std::stringstream old;
  old << in.rdbuf();
  std::string text = old.str();
  const std::string begin = "<!-- " + name + ":begin -->", end = "<!-- " + name + ":end -->";
  const size_t b = text.find(begin), e = text.find(end);
  if (b == std::string::npos || e == std::string::npos || e < b) return false;
  text = text.substr(0, b + begin.size()) + "\n" + body + text.substr(e);
  std::ofstream(path) << text;
  return true;
}

}  // namespace bimdf::bench

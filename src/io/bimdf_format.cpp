// libSatsuma's `.bimdf` text format (docs/formats.md, ../shared/reference/libsatsuma.md §3.1),
// read strictly and written in decimal. Layout after an optional free first line:
//   N  d_0 … d_{N−1}  M  then M records `u v hu hv lower upper COST`.
// bimdf extensions, used by the writer only when needed: outer edges (`v` = -1, `hv` = -),
// `inf`/`-inf` bounds, cost tags Z (zero with guess), L, B, P. A first line starting with
// "# bimdf-format" marks such a file; only then is 2147483647 a finite number instead of
// libSatsuma's infinity.
#include <algorithm>
#include <limits>
#include <ostream>
#include <sstream>

#include "bimdf/io.hpp"
#include "report_issue.hpp"
#include "text_scan.hpp"

namespace bimdf {
namespace {

using detail::quote;
using detail::TextScanner;
using detail::Token;

constexpr int64_t kLibsatsumaInfinity = std::numeric_limits<int32_t>::max();
constexpr std::string_view kExtendedHeader = "# bimdf-format 1";
// Nesting limit for `+` sums: deep enough for any real model, shallow enough that a hostile
// file cannot exhaust the stack.
constexpr int kMaxSumDepth = 64;

class BimdfReader {
 public:
  BimdfReader(std::string_view text, const std::string& source) : scan_(text, source) {
    extended_ = text.substr(0, kExtendedHeader.size()) == kExtendedHeader;
    // libSatsuma ignores its first line; we do so when it does not start with a number, so that
    // hand-written files without a comment line also read.
    Token first = scan_.peek();
    double ignored;
    if (!first.text.empty() && first.line == 1 && !detail::parse_double(first.text, ignored))
      scan_.skip_line();
  }

  Problem read() {
    Problem p;
    const int64_t n = read_count("the node count");
    node_line_.reserve(static_cast<size_t>(n));
    for (int64_t v = 0; v < n; ++v) {
      const int line = scan_.peek().line;
      p.add_node(scan_.expect_int("the demand of node " + std::to_string(v) + " (an integer)"));
      node_line_.push_back(line);
    }
    const int64_t m = read_count("the edge count");
    edge_line_.reserve(static_cast<size_t>(m));
    // An edge takes at least 13 bytes ("u v h h l u K"): a declared count beyond what the file
    // can hold does not reserve more than that.
    p.reserve(static_cast<int>(n), static_cast<int>(std::min<uint64_t>(
                                       static_cast<uint64_t>(m), scan_.remaining() / 13 + 1)));
    for (int64_t e = 0; e < m; ++e) read_edge(p, static_cast<int>(e), static_cast<int>(n));
    if (Token t = scan_.next(); !t.text.empty())
      scan_.fail(t.line, "unexpected token " + quote(t.text) + " after the last edge (the file declares " +
                             std::to_string(m) + " edges)");
    detail::validate_or_throw(p, scan_.source(), [&](const ProblemIssue& issue) {
      switch (issue.where) {
        case ProblemIssue::Where::Node:
          return std::to_string(node_line_[issue.index]);
        case ProblemIssue::Where::Edge:
          return std::to_string(edge_line_[issue.index]);
        default:
          return std::string();
      }
    }, /*location_names_field=*/false);
    return p;
  }

 private:
  int64_t read_count(const std::string& what) {
    const Token t = scan_.peek();
    const int64_t count = scan_.expect_int(what + " (a non-negative integer)");
    if (count < 0) scan_.fail(t.line, what + " must be >= 0, got " + std::to_string(count));
    // Every item takes at least two bytes; this rejects absurd counts before allocating.
    if (static_cast<uint64_t>(count) > scan_.remaining() / 2 + 1 ||
        count > std::numeric_limits<int>::max())
      scan_.fail(t.line, what + " " + std::to_string(count) +
                             " is more than the rest of the file can hold (truncated file?)");
    return count;
  }

  std::string edge_str(int e) const { return "edge " + std::to_string(e); }

  int read_node_id(const std::string& what, int n) {
    const Token t = scan_.peek();
    const int64_t id = scan_.expect_int(what);
    if (id < 0 || id >= n)
      scan_.fail(t.line, what + ": node id " + std::to_string(id) + " is out of range [0, " +
                             std::to_string(n) + ")");
    return static_cast<int>(id);
  }

  bool read_head_flag(const std::string& what) {
    const Token t = scan_.expect(what);
    if (t.text == "1") return true;
    if (t.text == "0") return false;
    scan_.fail(t.line, "expected " + what + " (1 = head, 0 = tail), got " + quote(t.text));
  }

  int64_t read_bound(const std::string& what, bool is_upper) {
    const Token t = scan_.expect(what);
    if (t.text == "inf" || t.text == "+inf" || t.text == "infinity") return kInfinity;
    if (t.text == "-inf" || t.text == "-infinity") return -kInfinity;
    int64_t v = 0;
    if (!detail::parse_int64(t.text, v))
      scan_.fail(t.line, "expected " + what + " (an integer or inf), got " + quote(t.text));
    if (is_upper && !extended_ && v == kLibsatsumaInfinity) return kInfinity;
    return v;
  }

  void read_edge(Problem& p, int e, int n) {
    const std::string ed = edge_str(e);
    edge_line_.push_back(scan_.peek().line);
    const int u = read_node_id(ed + ": the first node id", n);
    // The second node is -1 for an outer edge (extension); its head flag is then "-".
    const Token vt = scan_.peek();
    int64_t v_raw = 0;
    const bool outer = detail::parse_int64(vt.text, v_raw) && v_raw == -1;
    int v = kNoNode;
    if (outer)
      scan_.next();
    else
      v = read_node_id(ed + ": the second node id (or -1 for an outer edge)", n);
    const bool hu = read_head_flag(ed + ": the head flag of the first end");
    bool hv = false;
    if (outer) {
      const Token t = scan_.expect(ed + ": '-' (no second end)");
      if (t.text != "-")
        scan_.fail(t.line, ed + ": an outer edge (second node -1) needs '-' as its second head flag, got " +
                               quote(t.text));
    } else {
      hv = read_head_flag(ed + ": the head flag of the second end");
    }
    const int64_t lo = read_bound(ed + ": the lower bound", false);
    const int64_t up = read_bound(ed + ": the upper bound", true);
    Cost c = read_cost(ed, 0);
    std::optional<End> second;
    if (!outer) second = End{v, hv};
    p.add_edge(End{u, hu}, second, lo, up, std::move(c));
  }

  Cost read_cost(const std::string& ed, int depth) {
    const Token tag = scan_.expect(ed + ": a cost (0, A, Q, S, +, Z, L, B or P)");
    const std::string what = ed + ": cost " + std::string(tag.text);
    auto num = [&](const char* param) { return scan_.expect_double(what + " " + param + " (a number)"); };
    if (tag.text == "0") return Cost::zero();
    if (tag.text == "Z") return Cost::zero(scan_.expect_int(what + " guess (an integer)"));
    if (tag.text == "L") return Cost::linear(num("slope"));
    if (tag.text == "A" || tag.text == "Q") {
      const double t = num("target");
      const double w = num("weight");
      return tag.text == "A" ? Cost::abs_deviation(t, w) : Cost::quad_deviation(t, w);
    }
    if (tag.text == "B") {
      const double t = num("target");
      const double below = num("weight_below");
      return Cost::asym_abs_deviation(t, below, num("weight_above"));
    }
    if (tag.text == "S") {
      const double t = num("target");
      const double w = num("weight");
      return Cost::scale_factor(t, w, num("eps"));
    }
    if (tag.text == "P") {
      const int64_t first = scan_.expect_int(what + " first point (an integer)");
      const int64_t k = read_count(what + " value count");
      std::vector<double> values;
      values.reserve(static_cast<size_t>(k));
      for (int64_t i = 0; i < k; ++i) values.push_back(num(("value " + std::to_string(i)).c_str()));
      return Cost::piecewise_linear(first, std::move(values));
    }
    if (tag.text == "+") {
      if (depth >= kMaxSumDepth)
        scan_.fail(tag.line, ed + ": cost sums nested deeper than " + std::to_string(kMaxSumDepth));
      const int64_t k = read_count(what + " term count");
      std::vector<Cost> terms;
      terms.reserve(static_cast<size_t>(k));
      for (int64_t i = 0; i < k; ++i) terms.push_back(read_cost(ed, depth + 1));
      return Cost::sum(std::move(terms));
    }
    scan_.fail(tag.line, ed + ": unknown cost type " + quote(tag.text) +
                             ", expected 0, A, Q, S, +, Z, L, B or P");
  }

  TextScanner scan_;
  bool extended_ = false;
  std::vector<int> node_line_;
  std::vector<int> edge_line_;
};

class BimdfWriter {
 public:
  BimdfWriter(std::ostream& out, const Problem& p, bool compatible)
      : out_(out), p_(p), compatible_(compatible) {}

  void write() {
    out_ << (compatible_ ? std::string_view("# libSatsuma BiMDF file") : kExtendedHeader) << '\n';
    out_ << p_.num_nodes() << '\n';
    for (int v = 0; v < p_.num_nodes(); ++v) out_ << int_value(p_.demand[v], "node", v) << '\n';
    out_ << p_.num_edges() << '\n';
    for (int e = 0; e < p_.num_edges(); ++e) {
      const End a = p_.end_a[e], b = p_.end_b[e];
      out_ << a.node << ' ';
      if (b.node == kNoNode) {
        require(!compatible_, e, "outer edges (a single end) cannot be written");
        out_ << "-1 " << a.head << " - ";
      } else {
        out_ << b.node << ' ' << a.head << ' ' << b.head << ' ';
      }
      out_ << bound(p_.lower[e], e) << ' ' << bound(p_.upper[e], e) << ' ';
      write_cost(p_.cost[e], e);
      out_ << '\n';
    }
  }

 private:
  void require(bool ok, int e, const std::string& what) const {
    if (!ok)
      throw InputError("<bimdf writer>", "",
                       detail::describe_edge(p_, e) + ": " + what + " in libSatsuma-compatible .bimdf");
  }

  std::string int_value(int64_t v, const char* element, int id) const {
    if (compatible_ && (v >= kLibsatsumaInfinity || v < std::numeric_limits<int32_t>::min()))
      throw InputError("<bimdf writer>", "",
                       std::string(element) + " " + std::to_string(id) + ": value " + std::to_string(v) +
                           " is outside libSatsuma's 32-bit range");
    return std::to_string(v);
  }

  std::string bound(int64_t v, int e) const {
    if (v == kInfinity) return compatible_ ? std::to_string(kLibsatsumaInfinity) : "inf";
    if (v == -kInfinity) {
      require(!compatible_, e, "an infinite lower bound cannot be written");
      return "-inf";
    }
    return int_value(v, "edge", e);
  }

  void write_cost(const Cost& c, int e) {
    auto d = [](double v) { return detail::format_double(v); };
    switch (c.kind()) {
      case CostKind::Zero:
        // libSatsuma's format has no place for the guess; compatible output drops it as
        // libSatsuma's own writer does (it is a starting hint, not part of the problem).
        if (compatible_ || c.guess() == 0)
          out_ << '0';
        else
          out_ << "Z " << c.guess();
        return;
      case CostKind::AbsDeviation:
        out_ << "A " << d(c.target()) << ' ' << d(c.weight());
        return;
      case CostKind::QuadDeviation:
        out_ << "Q " << d(c.target()) << ' ' << d(c.weight());
        return;
      case CostKind::ScaleFactor:
        out_ << "S " << d(c.target()) << ' ' << d(c.weight()) << ' ' << d(c.eps());
        return;
      case CostKind::Sum:
        out_ << "+ " << c.terms().size();
        for (const Cost& t : c.terms()) {
          out_ << ' ';
          write_cost(t, e);
        }
        return;
      case CostKind::Linear:
        require(!compatible_, e, "a linear cost cannot be written");
        out_ << "L " << d(c.slope());
        return;
      case CostKind::AsymAbsDeviation:
        require(!compatible_, e, "an asymmetric deviation cost cannot be written");
        out_ << "B " << d(c.target()) << ' ' << d(c.weight_below()) << ' ' << d(c.weight_above());
        return;
      case CostKind::PiecewiseLinear:
        require(!compatible_, e, "a piecewise-linear cost cannot be written");
        out_ << "P " << c.first() << ' ' << c.values().size();
        for (double v : c.values()) out_ << ' ' << d(v);
        return;
    }
  }

  std::ostream& out_;
  const Problem& p_;
  bool compatible_;
};

}  // namespace

Problem parse_bimdf(std::string_view text, const std::string& source) {
  return BimdfReader(text, source).read();
}

void write_bimdf(std::ostream& out, const Problem& problem, const BimdfWriteOptions& options) {
  BimdfWriter(out, problem, options.libsatsuma_compatible).write();
}

std::string to_bimdf(const Problem& problem, const BimdfWriteOptions& options) {
  std::ostringstream s;
  write_bimdf(s, problem, options);
  return s.str();
}

}  // namespace bimdf

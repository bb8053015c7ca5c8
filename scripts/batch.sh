#!/usr/bin/env bash
# Runs every mesh of a folder through the bimdf CLI, in parallel (GNU parallel), and writes a CSV
# summary. Docs: docs/batch.md.
#
# Usage: scripts/batch.sh IN_DIR OUT_DIR [bimdf options...]
#   Every *.obj below IN_DIR (recursive) is one mesh, named after its file (X.obj -> X):
#     X.obj with X.patch beside it (QuadWild layout) -> bimdf remesh X.obj -o OUT_DIR/X.obj --report OUT_DIR/X.json [options]
#     any other X.obj (a quad mesh)                  -> bimdf requantize X.obj -o OUT_DIR/X.obj --report OUT_DIR/X.json [options]
#   Options after OUT_DIR go to every bimdf call unchanged. OUT_DIR is created; it must not be
#   IN_DIR nor lie inside it. Two meshes with the same name are refused.
#   A failing mesh does not stop the others: its stderr stays in OUT_DIR/X.err, a line
#   "NAME<TAB>EXIT_CODE<TAB>first error line" goes to OUT_DIR/failed.log. A successful mesh has no
#   X.err (its warnings, if any, are in X.warn and in the report). Also written: OUT_DIR/inputs.tsv
#   (the mesh list: name, kind, input path), OUT_DIR/joblog.tsv (GNU parallel's --joblog) and
#   OUT_DIR/summary.csv (one row per mesh, sorted by name).
#   Exit status: 0 all meshes done, 1 some failed, 2 usage error (missing IN_DIR, no .obj in it,
#   bimdf or parallel not found, OUT_DIR = IN_DIR, ...).
#
# Steps on their own (the full run is --list, then --one per mesh, then --summary; see the Slurm
# job array in docs/batch.md):
#   scripts/batch.sh --list IN_DIR OUT_DIR          write OUT_DIR/inputs.tsv, start a new failed.log,
#                                                   print the number of meshes
#   scripts/batch.sh --task N OUT_DIR [options]     run mesh N (line N of OUT_DIR/inputs.tsv, from 1)
#   scripts/batch.sh --one OUT_DIR NAME KIND INPUT [options]   run one mesh (KIND remesh|requantize)
#   scripts/batch.sh --summary OUT_DIR              write OUT_DIR/summary.csv from inputs.tsv, the
#                                                   reports and the .err files; exit 0 or 1 as above
#
# Environment:
#   BIMDF  the CLI (default: build/bin/bimdf of this repository if present, else bimdf on PATH)
#   JOBS   parallel jobs (parallel -j; default: the number of cores, nproc)
# The progress bar (parallel --bar) is drawn on stderr only when stderr is a terminal.
set -euo pipefail

self="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")"
root="$(cd "$(dirname "$self")/.." && pwd)"

die() {
  local code=$1
  shift
  printf 'batch.sh: %s\n' "$*" >&2
  exit "$code"
}

usage() {
  sed -n '/^# Usage:/,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "$self"
}

# The CLI as an absolute path (so that parallel jobs and cluster tasks find it from anywhere).
resolve_bimdf() {
  local b="${BIMDF:-}"
  if [[ -z $b ]]; then
    if [[ -x $root/build/bin/bimdf ]]; then
      b="$root/build/bin/bimdf"
    else
      b="$(command -v bimdf || true)"
      [[ -n $b ]] || die 2 "bimdf CLI not found: set BIMDF, build $root/build/bin/bimdf or put bimdf on PATH"
    fi
  elif [[ $b == */* ]]; then
    [[ -f $b && -x $b ]] || die 2 "BIMDF=$b is not an executable file"
  else
    local p
    p="$(command -v "$b" || true)"
    [[ -n $p ]] || die 2 "BIMDF=$b: no such command on PATH"
    b=$p
  fi
  [[ $b == /* ]] || b="$(cd "$(dirname "$b")" && pwd)/$(basename "$b")"
  printf '%s\n' "$b"
}

# Writes OUT_DIR/inputs.tsv (NAME<TAB>KIND<TAB>ABSOLUTE_INPUT, sorted by name), empties
# failed.log, removes an old summary.csv; prints the number of meshes.
check_dirs() {
  local in=$1 out=$2
  [[ -d $in ]] || die 2 "IN_DIR '$in' does not exist or is not a directory"
  local in_abs out_abs
  in_abs="$(cd "$in" && pwd -P)"
  out_abs="$(realpath -m -- "$out")"
  if [[ $out_abs == "$in_abs" || $out_abs == "$in_abs"/* ]]; then
    die 2 "OUT_DIR '$out' is IN_DIR '$in' or inside it: outputs could overwrite inputs; choose another folder"
  fi
}

list_inputs() {
  local in=$1 out=$2
  check_dirs "$in" "$out"
  local in_abs out_abs
  in_abs="$(cd "$in" && pwd -P)"
  out_abs="$(realpath -m -- "$out")"
  local -A seen=()
  local lines=() f name dir kind real
  while IFS= read -r -d '' f; do
    name="$(basename "$f" .obj)"
    dir="$(dirname "$f")"
    [[ $f != *$'\t'* && $f != *$'\n'* ]] || die 2 "tab or newline in the file name '$f' is not supported"
    [[ -z ${seen[$name]:-} ]] || die 2 "two meshes named '$name': ${seen[$name]} and $f (outputs would collide)"
    seen[$name]=$f
    real="$(realpath -- "$f")"
    [[ "$(dirname "$real")" != "$out_abs" ]] || die 2 "input '$f' is a link into OUT_DIR '$out'"
    if [[ -f $dir/$name.patch ]]; then kind=remesh; else kind=requantize; fi
    lines+=("$name"$'\t'"$kind"$'\t'"$f")
  done < <(find "$in_abs" -type f -name '*.obj' -print0)
  ((${#lines[@]} > 0)) || die 2 "IN_DIR '$in' holds no .obj file"
  mkdir -p -- "$out"
  printf '%s\n' "${lines[@]}" | LC_ALL=C sort -t $'\t' -k1,1 >"$out/inputs.tsv"
  : >"$out/failed.log"
  rm -f -- "$out/summary.csv"
  printf '%s\n' "${#lines[@]}"
}

# Runs one mesh; returns bimdf's exit code.
run_one() {
  (($# >= 4)) || die 2 "--one needs OUT_DIR NAME KIND INPUT"
  local out=$1 name=$2 kind=$3 input=$4
  shift 4
  [[ $kind == remesh || $kind == requantize ]] || die 2 "kind '$kind' is neither remesh nor requantize"
  local bimdf
  bimdf="$(resolve_bimdf)"
  local obj="$out/$name.obj" report="$out/$name.json" err="$out/$name.err"
  rm -f -- "$obj" "$report" "$err" "$out/$name.warn"
  local rc=0
  "$bimdf" "$kind" "$input" -o "$obj" --report "$report" "$@" >/dev/null 2>"$err" || rc=$?
  if ((rc == 0)); then
    if [[ -s $err ]]; then mv -f -- "$err" "$out/$name.warn"; else rm -f -- "$err"; fi
    return 0
  fi
  local msg
  msg="$(grep -m1 -v '^[[:space:]]*$' "$err" || true)"
  [[ -n $msg ]] || msg="(no error output)"
  # One short write with O_APPEND: lines of concurrent jobs do not interleave.
  printf '%s\t%s\t%s\n' "$name" "$rc" "${msg//$'\t'/ }" >>"$out/failed.log"
  return "$rc"
}

run_task() {
  (($# >= 2)) || die 2 "--task needs N OUT_DIR"
  local n=$1 out=$2
  shift 2
  [[ $n =~ ^[1-9][0-9]*$ ]] || die 2 "--task: N must be a positive integer, got '$n'"
  [[ -f $out/inputs.tsv ]] || die 2 "no $out/inputs.tsv: run scripts/batch.sh --list IN_DIR $out first"
  local line name kind input
  line="$(sed -n "${n}p" "$out/inputs.tsv")"
  [[ -n $line ]] || die 2 "--task $n: $out/inputs.tsv has only $(wc -l <"$out/inputs.tsv") meshes"
  IFS=$'\t' read -r name kind input <<<"$line"
  run_one "$out" "$name" "$kind" "$input" "$@"
}

# Reads OUT_DIR/inputs.tsv, failed.log, X.err and X.json; writes summary.csv; prints one line.
# Exits 0 if every mesh is done, 1 otherwise.
summary_py='
import csv, json, os, sys
out = sys.argv[1]
codes = {}
if os.path.exists(os.path.join(out, "failed.log")):
    with open(os.path.join(out, "failed.log"), encoding="utf-8", errors="replace") as f:
        for line in f:
            parts = line.rstrip("\n").split("\t")
            if len(parts) >= 2:
                codes[parts[0]] = parts[1]
with open(os.path.join(out, "inputs.tsv"), encoding="utf-8") as f:
    meshes = sorted(tuple(line.rstrip("\n").split("\t")[:2]) for line in f if line.strip())

def get(d, *keys):
    for k in keys:
        if not isinstance(d, dict) or k not in d:
            return ""
        d = d[k]
    return d

columns = ["name", "kind", "status", "exit_code", "quads", "sj_min", "sj_mean", "sj_p5",
           "inverted", "time_s"]
done = 0
with open(os.path.join(out, "summary.csv"), "w", newline="", encoding="utf-8") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(columns)
    for name, kind in meshes:
        report = None
        if not os.path.exists(os.path.join(out, name + ".err")):
            try:
                with open(os.path.join(out, name + ".json"), encoding="utf-8") as r:
                    report = json.load(r)
            except (OSError, ValueError):
                report = None
        if not isinstance(report, dict):
            w.writerow([name, kind, "failed", codes.get(name, "")] + [""] * 6)
            continue
        done += 1
        m = report.get("metrics", {})
        sj = get(m, "scaled_jacobian")
        quads = report.get("quads", get(m, "faces"))
        w.writerow([name, kind, report.get("status") or get(report, "quantization", "status"), 0,
                    quads, get(sj, "min"), get(sj, "mean"), get(sj, "p5"),
                    get(m, "inverted"), get(report, "time", "total_s")])
failed = len(meshes) - done
csv_path = os.path.join(out, "summary.csv")
print(f"{len(meshes)} meshes: {done} done, {failed} failed; summary {csv_path}")
sys.exit(1 if failed else 0)
'

summarize() {
  (($# == 1)) || die 2 "--summary needs OUT_DIR"
  [[ -f $1/inputs.tsv ]] || die 2 "no $1/inputs.tsv: not an output folder of scripts/batch.sh"
  python3 -c "$summary_py" "$1"
}

run_all() {
  (($# >= 2)) || {
    usage >&2
    exit 2
  }
  local in=$1 out=$2
  shift 2
  check_dirs "$in" "$out"
  BIMDF="$(resolve_bimdf)"
  export BIMDF
  command -v parallel >/dev/null || die 2 "GNU parallel not found (Debian/Ubuntu: apt-get install parallel)"
  command -v python3 >/dev/null || die 2 "python3 not found (needed for summary.csv)"
  list_inputs "$in" "$out" >/dev/null
  local jobs="${JOBS:-$(nproc)}" bar=()
  [[ -t 2 ]] && bar=(--bar)
  # parallel exits with the number of failed jobs (1-100, 101 for more), which the summary counts
  # itself, or 255 for its own errors (e.g. a bad JOBS).
  local prc=0
  parallel --colsep '\t' -j "$jobs" "${bar[@]}" --joblog "$out/joblog.tsv" -q \
    bash "$self" --one "$out" '{1}' '{2}' '{3}' "$@" :::: "$out/inputs.tsv" || prc=$?
  ((prc <= 101)) || die 2 "GNU parallel failed (exit $prc; JOBS='$jobs')"
  summarize "$out"
}

case "${1:-}" in
  -h | --help)
    usage
    ;;
  --list)
    (($# == 3)) || die 2 "--list needs IN_DIR OUT_DIR"
    list_inputs "$2" "$3"
    ;;
  --task)
    shift
    run_task "$@"
    ;;
  --one)
    shift
    run_one "$@"
    ;;
  --summary)
    shift
    summarize "$@"
    ;;
  -*)
    die 2 "unknown option '$1' (see scripts/batch.sh --help)"
    ;;
  *)
    run_all "$@"
    ;;
esac

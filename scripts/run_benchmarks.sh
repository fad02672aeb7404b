#!/usr/bin/env bash
# Builds the benchmarks (Release) with their peers (VTK, GUDHI) and runs each benchmark in its own process,
# so that its peak resident memory can be reported. Output: benchmark/results.txt (or RESULTS=...).
# Filter with FILTER='regex' (default: everything). Run on an otherwise idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
FEATURERECON_WITH_VTK=1 FEATURERECON_WITH_OPEN3D=1 bash scripts/install_dependencies.sh
if ! command -v /usr/bin/time > /dev/null; then apt-get install -y -q time > /dev/null; fi
BUILD_DIR=${BUILD_DIR:-build-bench} bash scripts/build.sh -DFEATURERECON_BUILD_TESTS=OFF \
  -DFEATURERECON_BUILD_EXAMPLES=OFF -DFEATURERECON_BUILD_TOOLS=OFF -DFEATURERECON_BUILD_BENCHMARKS=ON
bin=${BUILD_DIR:-build-bench}/benchmark
results=${RESULTS:-benchmark/results.txt}
filter=${FILTER:-.}
: > "$results"
for program in bench_reeb_graph bench_rips_graph bench_skeleton_end_to_end bench_sample_elimination bench_lloyd bench_discrete_lloyd bench_bilateral_filter; do
  for name in $("$bin/$program" --benchmark_list_tests | grep -E "$filter"); do
    /usr/bin/time -f "peak_rss_kb %M" "$bin/$program" --benchmark_filter="^${name}\$" 2>&1 \
      | grep -E "^(reeb|simplify|dead_ends|rips|skeleton|sampling|knn8|mds2000)/|peak_rss_kb" | tr '\n' ' ' | sed 's/$/\n/' | tee -a "$results"
  done
done
echo "results in $results"

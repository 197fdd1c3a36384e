#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# run_fuzz.sh TARGET CORPUS SECONDS [RUNS]: fuzzes TARGET for SECONDS from a scratch copy of the
# seed corpus (libFuzzer adds to its corpus folder). With RUNS, at most RUNS inputs from a fixed
# random seed: the same inputs on every machine, so a test run does not pass or fail by luck.
# Fails, keeping the crash-* input in the scratch folder, when libFuzzer finds a crash, a leak or
# a sanitizer report.
set -euo pipefail
target=$1 corpus=$2 seconds=$3 runs=${4:--1}
scratch=$(mktemp -d "${TMPDIR:-/tmp}/hmcr_fuzz_run.XXXXXX")
cp -r "$corpus"/. "$scratch/corpus"
cd "$scratch"
if "$target" -max_total_time="$seconds" -max_len=65536 -timeout=20 -rss_limit_mb=4096 \
     -print_final_stats=1 -runs="$runs" $([ "$runs" -ge 0 ] && echo -seed=1) corpus 2> log; then
  grep -E "^stat::number_of_executed_runs|^stat::peak_rss" log || true
  rm -rf "$scratch"
else
  tail -n 40 log
  echo "run_fuzz.sh: finding kept in $scratch"
  exit 1
fi

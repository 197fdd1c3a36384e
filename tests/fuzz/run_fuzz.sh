#!/usr/bin/env bash
# run_fuzz.sh TARGET CORPUS SECONDS: fuzzes TARGET for SECONDS from a scratch copy of the seed
# corpus (libFuzzer adds to its corpus folder). Fails, keeping the crash-* input in the scratch
# folder, when libFuzzer finds a crash, a leak or a sanitizer report.
set -euo pipefail
target=$1 corpus=$2 seconds=$3
scratch=$(mktemp -d "${TMPDIR:-/tmp}/hmcr_fuzz_run.XXXXXX")
cp -r "$corpus"/. "$scratch/corpus"
cd "$scratch"
if "$target" -max_total_time="$seconds" -max_len=65536 -timeout=20 -rss_limit_mb=4096 \
     -print_final_stats=1 corpus 2> log; then
  grep -E "^stat::number_of_executed_runs|^stat::peak_rss" log || true
  rm -rf "$scratch"
else
  tail -n 40 log
  echo "run_fuzz.sh: finding kept in $scratch"
  exit 1
fi

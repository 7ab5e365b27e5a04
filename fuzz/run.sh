#!/usr/bin/env bash
# Runs each libFuzzer harness of fuzz/ for SECONDS, one worker, on the seeds of fuzz/corpus/<target>
# (and, for the loaders, scenarios/) and the corpus it grew before (BUILD/corpus/<target>).
# Findings go to BUILD/findings/; the exit status is non-zero if any target found one.
# Usage: fuzz/run.sh BUILD SECONDS [TARGET...]
set -uo pipefail
build=$1
seconds=$2
shift 2
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scenario overrides invsim)
here=$(cd "$(dirname "$0")" && pwd)
status=0
mkdir -p "$build/findings"
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"
  mkdir -p "$corpus"
  # -timeout=2: an input that takes 2 s is a finding (the loader must answer in well under one).
  # -rss_limit_mb: a document that needs 2 GB is a finding too.
  # The shipped scenarios seed the scenario and invsim loaders too: a malformed variant of a real
  # file reaches validation and the derived timing, where a variant of a toy stops at parsing.
  seeds=("$here/corpus/$t")
  [ "$t" != overrides ] && seeds+=("$here/../scenarios")
  echo "fuzz: $t for ${seconds} s (corpus $corpus, seeds ${seeds[*]})" >&2
  "$build/fuzz/chaser_fuzz_$t" "$corpus" "${seeds[@]}" \
    -max_total_time="$seconds" -timeout=2 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="$build/findings/$t-" -print_final_stats=1 || status=1
done
exit $status

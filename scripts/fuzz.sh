#!/usr/bin/env bash
# Builds the libFuzzer targets in fuzz/ in the sanitized build, build-asan/ (clang; configured by
# scripts/configure-sanitized.sh, shared with scripts/test-sanitized.sh, which builds them already), and runs
# each for SECONDS (default 60) on one core, one after the other (two at a time on a two-core machine ran
# a quarter to two thirds of the inputs each: docs/testing.md, "Robustness"). Corpora grow in
# build-asan/corpus/TARGET/ (seeded from effects/, tests/data/, fuzz/seeds/ and scenes/). The script fails when a fuzzer exits non-zero, when a target leaves
# any finding in build-asan/artifacts/TARGET/ (crash-*, leak-*, timeout-*, oom-*, slow-unit-*; findings of
# an earlier run stay there and keep failing until they are fixed and removed), or when a target ran no
# input. It runs every target before it exits. A finding's lines of the log (the sanitizer's or libFuzzer's
# error, an uncaught exception's type and text) and its input, base64, are printed: CI's log reproduces it.
# Every crash found is fixed and added to tests/data/malformed/ with its golden diagnostics.
#   scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/phase-times.sh
seconds="${1:-60}"
if [ $# -gt 0 ]; then shift; fi
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(fuzz_effect_parser fuzz_effect_compiler fuzz_compile_workers fuzz_sas_script fuzz_dds_file
           fuzz_compiled_effect_file fuzz_host_file)
  [ -f runtime/assets/include/runtime/SceneFile.h ] && targets+=(fuzz_scene_file)
fi

phase install-deps scripts/install-deps.sh >/dev/null
phase "fuzz configure+build" scripts/configure-sanitized.sh
# Only what the chosen targets need (fuzz_compile_workers depends on the worker in CMake): the CLI, which
# compiles the compiled-effect fuzzer's seeds, is the whole project (after test-sanitized.sh, built already).
build=("${targets[@]}")
[[ " ${targets[*]} " == *" fuzz_compiled_effect_file "* ]] && build+=(shadowfx)
phase "fuzz configure+build" cmake --build build-asan -j "$(nproc)" --target "${build[@]}"

root="$(pwd)"
seed() {  # seed TARGET: fills an empty corpus from the checked-in inputs
  local dir="build-asan/corpus/$1"
  mkdir -p "$dir"
  [ -n "$(ls -A "$dir")" ] && return 0
  case "$1" in
    fuzz_effect_parser | fuzz_effect_compiler | fuzz_compile_workers)
      find effects tests/data fuzz/seeds -name '*.fx' -o -name '*.fxh' | while read -r f; do
        [ "$(stat -c %s "$f")" -le 65536 ] && cp "$f" "$dir/$(echo "$f" | tr / _)"
      done ;;
    fuzz_sas_script)  # the value of every Script annotation
      grep -rhoE 'Script *= *"[^"]*"' effects tests/data | sed -E 's/^Script *= *"(.*)"$/\1/' | sort -u |
        while read -r s; do printf '%s' "$s" > "$dir/$(printf '%s' "$s" | md5sum | cut -c1-16)"; done ;;
    fuzz_dds_file)  # one small file of each family: masks, float components, blocks, a DX10 header
      cp fuzz/seeds/*.dds "$dir/" ;;
    fuzz_compiled_effect_file)  # shipped effects whose files stay under -max_len, compiled by this build
      for effect in plain_lit back_faces id_buffer; do
        build-asan/samples/shadowfx/shadowfx compile "effects/$effect.fx" --out "$dir/$effect.sfxo"
      done ;;
    fuzz_host_file)  # the host files of the tests and the docs
      find tests/data/host docs/host-files -name '*.json' | while read -r f; do cp "$f" "$dir/$(echo "$f" | tr / _)"; done ;;
    fuzz_scene_file)
      find scenes tests/data -name '*.json' 2>/dev/null | while read -r f; do cp "$f" "$dir/$(echo "$f" | tr / _)"; done
      [ -n "$(ls -A "$dir")" ] || echo '{}' > "$dir/empty.json" ;;
  esac
}

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" LP_NUM_THREADS=1
status=0
phase_start
for target in "${targets[@]}"; do
  seed "$target"
  mkdir -p "build-asan/artifacts/$target"
  # Run in an empty folder: the scene loader resolves mesh paths there, not in the repository.
  work="$(mktemp -d)"
  echo "== $target: ${seconds}s"
  # The fuzzer's own exit status (a crash, leak, timeout or OOM exits non-zero), its artifacts, and the
  # number of inputs it ran: a target that starts and runs nothing tests nothing.
  log="$root/build-asan/$target.log"
  fuzzer_status=0
  (cd "$work" && "$root/build-asan/fuzz/$target" -max_total_time="$seconds" -max_len=65536 -timeout=20 \
     -rss_limit_mb=3072 -print_final_stats=1 -artifact_prefix="$root/build-asan/artifacts/$target/" \
     "$root/build-asan/corpus/$target" >"$log" 2>&1) || fuzzer_status=$?
  grep -E '^(#[0-9]+.*DONE|stat::|==[0-9]+== ?ERROR|SUMMARY|terminate called|  what\(\))' "$log" ||
    echo "$target: no statistics in $log"
  if [ "$fuzzer_status" -ne 0 ]; then
    echo "$target: the fuzzer exited with status $fuzzer_status (log: build-asan/$target.log)"; status=1
  fi
  findings=$(find "build-asan/artifacts/$target" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' \
    -o -name 'timeout-*' -o -name 'oom-*' -o -name 'slow-unit-*' \) | sort)
  if [ -n "$findings" ]; then
    echo "$target: findings in build-asan/artifacts/$target/:"; echo "$findings"; status=1
    # Where the artifacts are out of reach (a CI machine), the log alone must let a developer reproduce
    # the finding: each input's first 4 KiB, base64 (`base64 -d > input`, then run the target on it).
    for finding in $findings; do
      echo "$finding ($(stat -c %s "$finding") bytes), base64 of its first 4 KiB:"
      head -c 4096 "$finding" | base64
    done
  fi
  executed=$(sed -n 's/^stat::number_of_executed_units: *\([0-9]*\).*/\1/p' "$log" | tail -1)
  if [ "${executed:-0}" -eq 0 ]; then
    echo "$target: ran no input (log: build-asan/$target.log)"; status=1
  fi
  echo "corpus: $(ls "build-asan/corpus/$target" | wc -l) inputs"
  rm -rf "$work"
done
phase_end "fuzz (${#targets[@]} targets x ${seconds} s)" "$status"
exit $status

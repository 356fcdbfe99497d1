#!/usr/bin/env bash
# Fuzzes every mesh reader (OBJ, PLY, STL, OFF, glTF/GLB) with libFuzzer under ASan+UBSan for
# SECONDS each (default 60): installs clang (and libFuzzer's runtime) if missing, builds the
# harnesses of fuzz/ with clang in build-fuzz/ (-DHLENS_FUZZ=ON) and runs each on a copy of its seed
# corpus fuzz/corpus/<format>/ (the copy, build-fuzz/corpus/, is what grows; the repository is
# never written). Exits non-zero if any harness finds a crash, a sanitizer report, a leak, a time-out
# or an out-of-memory; the input that did it is saved in build-fuzz/artifacts/ and the command that
# replays it is printed. CI runs it from scripts/test.sh.
#
#   bash scripts/fuzz.sh [SECONDS]
#   build-fuzz/bin/fuzz_obj build-fuzz/artifacts/obj/crash-...    # replay one input
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${1:-60}"
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "usage: scripts/fuzz.sh [SECONDS]   (seconds per harness, default 60)" >&2
  exit 2
fi
formats=(obj ply stl off gltf)

# libFuzzer (libclang_rt.fuzzer) is in libclang-rt-14-dev, which clang only recommends.
bash scripts/install-deps.sh clang libclang-rt-14-dev

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ -DHLENS_FUZZ=ON \
  -DHLENS_BUILD_TESTS=OFF -DHLENS_BUILD_BENCH=OFF -DHLENS_BUILD_GUI=OFF
targets=()
for f in "${formats[@]}"; do targets+=("fuzz_$f"); done
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"

export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
failed=()
for f in "${formats[@]}"; do
  corpus="build-fuzz/corpus/$f" artifacts="build-fuzz/artifacts/$f"
  rm -rf "$artifacts"
  mkdir -p "$corpus" "$artifacts"
  cp -f fuzz/corpus/"$f"/* "$corpus"/
  log="build-fuzz/fuzz_$f.log"
  echo "fuzz.sh: fuzz_$f for ${seconds} s (corpus $corpus, log $log)"
  dict=()
  [ -f "fuzz/$f.dict" ] && dict=(-dict="fuzz/$f.dict")
  status=0
  build-fuzz/bin/fuzz_"$f" "$corpus" -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=65536 \
    -timeout=25 -print_final_stats=1 -artifact_prefix="$artifacts/" "${dict[@]}" >"$log" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    echo "fuzz.sh: fuzz_$f FAILED (exit $status); the end of $log:" >&2
    tail -n 60 "$log" >&2
    for a in "$artifacts"/*; do
      [ -e "$a" ] && echo "fuzz.sh: replay with: build-fuzz/bin/fuzz_$f $a" >&2
    done
    failed+=("$f")
  else
    grep -E '^stat::number_of_executed_units|^Done ' "$log" | tr '\n' ' ' || true
    echo
  fi
done

if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: FAILED: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz.sh: no crash in ${#formats[@]} harnesses x ${seconds} s"

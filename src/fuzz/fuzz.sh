#!/usr/bin/env bash
# ./touchline fuzz [--minutes N] [--target NAME]
# Fuzzes every decoder of outside input in the console with Jazzer (coverage-guided, libFuzzer
# inside the JVM), one target after the other for N minutes each (default 1), then the
# firmware's C libFuzzer targets for as long when clang is there. A finding (an exception the
# decoder does not declare, a broken property, a stack overflow, out-of-memory, an input that
# takes longer than 10 s) is written to src/test/resources/fuzz/<target>/ (Java) or
# robot-side/firmware/fuzz/corpus_<target>/ (C); the normal suite replays those files
# (FuzzCorpusTest, ctest). See docs/testing.md, "Fuzzing".
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
say() { printf '\033[1;34m[touchline fuzz]\033[0m %s\n' "$*" >&2; }
die() { printf '\033[1;31m[touchline fuzz]\033[0m %s\n' "$*" >&2; exit 1; }

JAVA_TARGETS=(framing message gamecontroller return-packet reliable mixed-value jpeg nao-param trailer recording serve-client gc-monitor ros2-definition ros2-cdr)
C_TARGETS=(gs1500 process auth)
minutes=1
only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --minutes) minutes=${2:?--minutes needs a number}; shift 2 ;;
    --target) only=${2:?--target needs a name}; shift 2 ;;
    -h|--help)
      echo "usage: ./touchline fuzz [--minutes N] [--target NAME]"
      echo "  Java targets: ${JAVA_TARGETS[*]}"
      echo "  C targets (clang): ${C_TARGETS[*]}"
      exit 0 ;;
    *) die "unknown option $1 (try --help)" ;;
  esac
done
[[ "$minutes" =~ ^[0-9]+$ ]] && [ "$minutes" -ge 1 ] || die "--minutes wants a whole number of minutes, got '$minutes'"
seconds=$((minutes * 60))
if [ -n "$only" ] && [[ ! " ${JAVA_TARGETS[*]} ${C_TARGETS[*]} " =~ " $only " ]]; then
  die "no target named '$only'; targets: ${JAVA_TARGETS[*]} ${C_TARGETS[*]}"
fi
wanted() { [ -z "$only" ] || [ "$only" = "$1" ]; }

found=0
java_ran=0
for t in "${JAVA_TARGETS[@]}"; do
  wanted "$t" || continue
  if [ "$java_ran" = 0 ]; then
    say "building the console and the fuzz harness (Maven)"
    mvn -q -B -DskipTests test-compile dependency:build-classpath -Dmdep.includeScope=test \
      -Dmdep.outputFile=target/fuzz-classpath.txt
    java_ran=1
  fi
  work="target/fuzz/$t"
  findings="src/test/resources/fuzz/$t"
  mkdir -p "$work/corpus" "$findings"
  before=$(find "$findings" -type f | wc -l)
  say "fuzzing $t for $minutes min (log: $work/log)"
  # A recording's seeds are whole MCAP files (one or two, every compression): they need room.
  max_len=16384
  [ "$t" = recording ] && max_len=262144
  # The serve-client target talks to its own server on 127.0.0.1: Jazzer's request-forgery
  # detector (which refuses every connection) is off for it.
  hooks=()
  [ "$t" = serve-client ] && hooks=(--disabled_hooks=com.code_intelligence.jazzer.sanitizers.ServerSideRequestForgery)
  # Single-threaded, a bounded heap; the harness writes its seeds into the work corpus first.
  # Netty without sun.misc.Unsafe: Jazzer's Unsafe sanitizer breaks its queues (serve-client).
  java -Xmx1g -Dio.netty.noUnsafe=true -Dtouchline.fuzz.target="$t" -Dtouchline.fuzz.seeds="$work/corpus" \
    -cp "target/test-classes:target/classes:$(cat target/fuzz-classpath.txt)" \
    com.code_intelligence.jazzer.Jazzer --target_class=touchline.fuzz.JazzerEntry \
    --instrumentation_includes='touchline.**' ${hooks[@]+"${hooks[@]}"} --keep_going=50 --reproducer_path="$work" \
    -max_total_time="$seconds" -max_len="$max_len" -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$findings/" "$work/corpus" "$findings" >"$work/log" 2>&1 || true
  after=$(find "$findings" -type f | wc -l)
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/log" | grep -o '[0-9]*$' || echo "?")
  say "$t: $runs inputs, $((after - before)) new finding(s) in $findings"
  found=$((found + after - before))
done

c_wanted=0
for t in "${C_TARGETS[@]}"; do wanted "$t" && c_wanted=1; done
if [ "$c_wanted" = 1 ]; then
  if command -v clang >/dev/null; then
    BUILD="$ROOT/robot-side/build"
    say "building the firmware fuzz targets (clang, libFuzzer + ASan/UBSan)"
    cmake -S robot-side -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
    for t in "${C_TARGETS[@]}"; do
      wanted "$t" || continue
      cmake --build "$BUILD" --target "fw_fuzz_${t}_build" >/dev/null
      corpus="robot-side/firmware/fuzz/corpus_$t"
      work="$BUILD/fuzz_work_$t"
      mkdir -p "$work"
      before=$(find "$corpus" -type f | wc -l)
      say "fuzzing firmware $t for $minutes min (log: $work/log)"
      ASAN_OPTIONS=detect_leaks=1 "$BUILD/bin/fw_fuzz_$t" -max_total_time="$seconds" -max_len=1600 -timeout=10 \
        -print_final_stats=1 -artifact_prefix="$corpus/" "$work" "$corpus" >"$work/log" 2>&1 || true
      after=$(find "$corpus" -type f | wc -l)
      say "firmware $t: $((after - before)) new finding(s) in $corpus"
      found=$((found + after - before))
    done
  else
    say "clang not found: the firmware's C fuzz targets are skipped"
  fi
fi

if [ "$found" -gt 0 ]; then
  die "$found new finding(s): fix them, keep the files (the suite replays them) and commit both"
fi
say "no new findings"

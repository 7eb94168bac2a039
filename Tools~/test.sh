#!/usr/bin/env bash
# All the tests: NUnit solver tests (the same files Unity runs), conformance tests of the Unity.Mathematics
# stand-in, the GPU kernels on lavapipe against the CPU solver, package lint, type-check of the Unity side, Burst
# compatibility of what the Burst entry points reach (+ its self-test), shader check (+ its self-test), a quick run of the
# mesh write-back timing and a quick smoke run of the main job.
# Ends with one line "N passed, N failed" and exits non-zero on any failure.
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1
LOG_DIR="$(mktemp -d)"
trap 'rm -rf "$LOG_DIR"' EXIT
PASSED=0
FAILED=0

section() { echo; echo "=== $1"; }
add() { PASSED=$((PASSED + $1)); FAILED=$((FAILED + $2)); echo "--> $3: $1 passed, $2 failed"; }

# Reads the "RESULT <name> <passed> <failed>" line a check prints; a check that printed none failed.
run_check() {
  local name="$1"; shift
  local log="$LOG_DIR/$name.log"
  "$@" >"$log" 2>&1
  local rc=$?
  cat "$log"
  local line; line="$(grep -E '^RESULT ' "$log" | tail -n 1)"
  if [ -z "$line" ]; then add 0 1 "$name (no RESULT line, exit $rc)"; return; fi
  local p f; p="$(echo "$line" | awk '{print $3}')"; f="$(echo "$line" | awk '{print $4}')"
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
  add "$p" "$f" "$name"
}

section "setup"
if ! bash "Tools~/setup.sh"; then
  add 0 1 "setup"
  echo; echo "$PASSED passed, $FAILED failed"; exit 1
fi

# Runs one NUnit project and counts its summary line; a skipped test is not a passing test.
run_nunit() {
  local name="$1" project="$2"
  local log="$LOG_DIR/$name.log"
  dotnet test "$project" -c Release --no-restore -nologo >"$log" 2>&1
  local rc=$?
  grep -E "^\s+(Failed|Skipped) |Error Message|^\s+Expected|^\s+But was|error CS|Passed!|Failed!" -A1 "$log" | grep -v "^--$" | head -n 200
  local summary
  summary="$(grep -E "(Passed|Failed)! +- +Failed: +[0-9]+, +Passed: +[0-9]+, +Skipped: +[0-9]+" "$log" | tail -n 1)"
  if [ -z "$summary" ]; then
    tail -n 40 "$log"; add 0 1 "$name (no summary, exit $rc)"
  else
    local nf np ns
    nf="$(echo "$summary" | sed -E 's/.*Failed: +([0-9]+).*/\1/')"
    np="$(echo "$summary" | sed -E 's/.*Passed: +([0-9]+).*/\1/')"
    ns="$(echo "$summary" | sed -E 's/.*Skipped: +([0-9]+).*/\1/')"
    add "$np" "$((nf + ns))" "$name"
  fi
}

section "NUnit: Tests/Solvers"
run_nunit nunit "Tools~/DotNet/SoftBodyDynamics.Tests.Solvers/SoftBodyDynamics.Tests.Solvers.csproj"

section "NUnit: Unity.Mathematics stand-in conformance"
run_nunit mathematics-stand-in "Tools~/DotNet/SoftBodyDynamics.Tests.MathematicsStandIn/SoftBodyDynamics.Tests.MathematicsStandIn.csproj"

section "NUnit: headless runner (options, progress, report, summary, units)"
run_nunit runner "Tools~/DotNet/SoftBodyDynamics.Tests.Runner/SoftBodyDynamics.Tests.Runner.csproj"

section "NUnit: GPU kernels on lavapipe against the CPU solver"
run_nunit compute "Tools~/DotNet/SoftBodyDynamics.Tests.Compute/SoftBodyDynamics.Tests.Compute.csproj"

section "package lint"
run_check lint dotnet run --project "Tools~/PackageLint/PackageLint.csproj" -c Release -- "$ROOT"

section "type-check of the Unity side"
run_check typecheck bash "Tools~/TypeCheck/typecheck.sh"

section "Burst compatibility of everything a [BurstCompile] entry point reaches"
run_check burstcheck bash "Tools~/BurstCheck/burstcheck.sh"
run_check burstcheck-selftest bash "Tools~/BurstCheck/burstcheck.sh" --self-test

section "shader check"
run_check shadercheck bash "Tools~/ShaderCheck/shader-check.sh"
run_check shadercheck-selftest bash "Tools~/ShaderCheck/shader-check.sh" --self-test

section "mesh write-back timing (quick)"
run_check meshwriteback dotnet run -c Release --project "Tools~/DotNet/SoftBodyDynamics.MeshWriteBackTiming/SoftBodyDynamics.MeshWriteBackTiming.csproj" --no-restore -- --quick

section "main job smoke run (quick)"
smoke="$LOG_DIR/smoke"
if bash "Tools~/run.sh" --quick --repeats 3 --out "$smoke" >"$LOG_DIR/smoke.log" 2>&1 \
   && [ -s "$smoke/report.md" ] && [ -s "$smoke/results.csv" ] && ls "$smoke"/*.png >/dev/null 2>&1; then
  tail -n 5 "$LOG_DIR/smoke.log"; add 1 0 "main job smoke"
else
  tail -n 40 "$LOG_DIR/smoke.log"; add 0 1 "main job smoke"
fi

echo
echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]

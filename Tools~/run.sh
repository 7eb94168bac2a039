#!/usr/bin/env bash
# The main job: runs every benchmark scenario headless, prints one table per suite (scenario, method, size, ms per step,
# ns per item, items per second, metrics) and a progress line per scenario, and writes report.md (summary first),
# results.csv, timings.csv and PNG figures, including the GPU fluid kernels and the fluid renderer on lavapipe.
# Usage: bash Tools~/run.sh [--quick | --full] [--filter TEXT] [--method TEXT] [--out DIR] [--repeats N] [--help]
# The default run covers every suite with its sweeps cut to what keeps each figure's shape (minutes); --full runs the
# whole study (tens of minutes); --quick a few points of each suite. Default report folder: Reports~/latest.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
export SBD_RUN_STARTED="${SBD_RUN_STARTED:-$(date +%s)}"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
RUNNER="Tools~/DotNet/SoftBodyDynamics.Runner/bin/Release/net10.0/SoftBodyDynamics.Runner.dll"
for a in "$@"; do
  case "$a" in
    --help|-h)
      dotnet build "Tools~/DotNet/SoftBodyDynamics.Runner/SoftBodyDynamics.Runner.csproj" -c Release --verbosity quiet -nologo >/dev/null
      exec dotnet "$RUNNER" --help ;;
  esac
done
bash "Tools~/setup.sh" --no-restore
# One build of the runner and the two lavapipe programs (Tools~/DotNet/MainJob.slnx): restored and compiled in parallel.
echo "Building the runner and the lavapipe tools ..." >&2
dotnet build "Tools~/DotNet/MainJob.slnx" -c Release --verbosity quiet -nologo >/dev/null
exec dotnet "$RUNNER" --root "$ROOT" "$@"

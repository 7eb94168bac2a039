#!/usr/bin/env bash
# The main job: runs every benchmark scenario headless, prints the table (scenario, method, size,
# ms per step, ns per item, items per second, error metrics) and writes a Markdown report with PNG figures.
# Usage: bash Tools~/run.sh [--out DIR] [--quick] [--repeats N] [--filter TEXT] [--method TEXT]
# The full run includes the method study (suites MethodStudy*, tens of minutes); --quick runs a few points of each suite,
# --filter TEXT only the suites whose name contains TEXT (e.g. --filter MethodStudyCantilever), --method TEXT only the
# scenarios whose method contains TEXT (e.g. --method "Neo-Hookean implicit").
# Default report folder: Reports~/latest (relative to the package root).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
bash "Tools~/setup.sh"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
dotnet build "Tools~/DotNet/SoftBodyDynamics.Runner/SoftBodyDynamics.Runner.csproj" -c Release --no-restore --verbosity quiet -nologo >/dev/null
dotnet "Tools~/DotNet/SoftBodyDynamics.Runner/bin/Release/net10.0/SoftBodyDynamics.Runner.dll" "$@"

# The GPU fluid kernels on lavapipe, pass by pass next to the C# passes (a CPU-driver timing, not a GPU one), and the
# fluid renderer's images and accuracy figure, appended to the report; skipped when --filter or --method picks other suites.
out="Reports~/latest"; quick=""; gpu=1
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift ;;
    --quick) quick="--quick" ;;
    --filter) case "${2,,}" in *lavapipe*|*gpu*) ;; *) gpu=0 ;; esac; shift ;;
    --method) gpu=0; shift ;;
  esac
  shift
done
if [ "$gpu" -eq 1 ]; then
  dotnet run -c Release --no-restore --project "Tools~/DotNet/SoftBodyDynamics.LavapipeTiming/SoftBodyDynamics.LavapipeTiming.csproj" -- $quick --out "$out/lavapipe.md"
  { echo; echo "## GPU fluid kernels on lavapipe (CPU driver; not a GPU number)"; echo; cat "$out/lavapipe.md"; } >> "$out/report.md"
  # The screen-space fluid renderer on lavapipe: scenes, looks, passes (PNG) and its accuracy against cost.
  dotnet run -c Release --no-restore --project "Tools~/DotNet/SoftBodyDynamics.FluidSurfaceRender/SoftBodyDynamics.FluidSurfaceRender.csproj" -- $quick --out "$out"
  { echo; echo "## Screen-space fluid renderer on lavapipe"; echo; cat "$out/surface.md"; } >> "$out/report.md"
fi

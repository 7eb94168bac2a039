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

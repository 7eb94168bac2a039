#!/usr/bin/env bash
# Burst-compatibility check of every method reachable from a [BurstCompile] entry point, on the assemblies the
# type-check built (run Tools~/TypeCheck/typecheck.sh first). Ends with RESULT burstcheck <clean> <failing>.
# --self-test checks the rules on the fixtures in Fixtures.cs instead.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1 MSBUILDTERMINALLOGGER=off
if ! out="$(dotnet build "$here/BurstCheck.csproj" -c Release -nologo -v:q -tl:off -clp:NoSummary 2>&1)"; then
  echo "$out"
  echo "burstcheck: could not build the tool" >&2
  exit 2
fi
exec dotnet "$here/bin/Release/net10.0/BurstCheck.dll" "$root" "$@"

#!/usr/bin/env bash
# Type-checks every Unity assembly of the package (Runtime, Editor, Tests, Benchmarks) against the reference
# declarations of the Unity APIs in Tools~/UnityApi, without Unity. Prints PASS/FAIL per assembly and ends with
#   RESULT typecheck <passed> <failed>
# Exit code: 0 when every assembly compiles, 1 when one fails, 2 when the tool itself cannot run.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1 MSBUILDTERMINALLOGGER=off
if ! out="$(dotnet build "$here/TypeCheck.csproj" -c Release -nologo -v:q -tl:off -clp:NoSummary 2>&1)"; then
  echo "$out"
  echo "typecheck: could not build the type-check tool" >&2
  exit 2
fi
exec dotnet "$here/bin/Release/net10.0/TypeCheck.dll" "$root" "$@"

#!/usr/bin/env bash
# Installs what the headless commands need on a fresh Debian machine with the .NET SDK, and
# restores the .NET projects (not with --no-restore: the main job restores what it builds). Safe to run any number of
# times: it installs only what is missing.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

need=()
command -v glslangValidator >/dev/null 2>&1 || need+=(glslang-tools)
command -v spirv-val        >/dev/null 2>&1 || need+=(spirv-tools)
command -v gnuplot          >/dev/null 2>&1 || need+=(gnuplot-nox)
command -v spirv-cross      >/dev/null 2>&1 || need+=(spirv-cross)
command -v gcc              >/dev/null 2>&1 || need+=(gcc)
# The GPU kernels run on lavapipe (Mesa's CPU Vulkan driver) through Tools~/VulkanHost, built against Debian's loader.
[ -f /usr/share/vulkan/icd.d/lvp_icd.x86_64.json ] || need+=(mesa-vulkan-drivers)
[ -f /usr/include/vulkan/vulkan.h ]               || need+=(libvulkan-dev)
[ -f /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json ] || need+=(vulkan-validationlayers)
if [ ${#need[@]} -gt 0 ]; then
  echo "setup: installing Debian packages: ${need[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq >/dev/null
  $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi

if ! command -v dotnet >/dev/null 2>&1; then
  echo "setup: the .NET SDK (dotnet) is required and was not found on PATH" >&2
  exit 1
fi
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1
[ "${1:-}" = "--no-restore" ] && exit 0
for p in SoftBodyDynamics.Tests.Solvers SoftBodyDynamics.Tests.MathematicsStandIn SoftBodyDynamics.Tests.Runner SoftBodyDynamics.Tests.Compute SoftBodyDynamics.Runner SoftBodyDynamics.MeshWriteBackTiming SoftBodyDynamics.LavapipeTiming SoftBodyDynamics.FluidSurfaceRender; do
  dotnet restore "$ROOT/Tools~/DotNet/$p/$p.csproj" --verbosity quiet >/dev/null
done

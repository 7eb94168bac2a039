#!/usr/bin/env bash
# Builds libvkhost.so (the Vulkan compute host the .NET harness loads) into the folder given, default ./bin.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
OUT="${1:-$HERE/bin}"
mkdir -p "$OUT"
if [ ! -f "$OUT/libvkhost.so" ] || [ "$HERE/vkhost.c" -nt "$OUT/libvkhost.so" ]; then
  gcc -O2 -std=c11 -Wall -Wextra -Werror -shared -fPIC -fvisibility=hidden -o "$OUT/libvkhost.so" "$HERE/vkhost.c" -lvulkan
fi

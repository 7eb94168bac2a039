#!/usr/bin/env bash
# shader-check.sh: compile every Unity compute kernel of the package with glslang's HLSL
# front end and validate the SPIR-V with spirv-val. Runs without Unity and without a GPU.
#
#   bash Tools~/ShaderCheck/shader-check.sh              check every *.compute in the package
#   bash Tools~/ShaderCheck/shader-check.sh --self-test  check the checker on fixtures/
#
# Which files: every *.compute under the package root (this script's ../..), skipping
# folders whose name ends in "~" (Unity ignores them) and dot-folders.
# Which kernels: every "#pragma kernel NAME [DEFINE[=value] ...]" line that is not commented
# out with //. Per-kernel defines (Unity syntax) become -D flags for that kernel.
#
# Per kernel:
#   glslangValidator -D -V -S comp -e NAME --amb --target-env vulkan1.1 \
#       -I<include root> -I<package root> -I<file dir> [-DDEF ...] -o K.spv FILE
#   then: no "ERROR", no "Entry point not found", a [numthreads(...)] attribute on the
#   kernel function in the preprocessed source (glslang silently defaults to 1,1,1; Unity
#   rejects it), OpEntryPoint "NAME" present in spirv-dis, and
#   spirv-val --target-env vulkan1.1 K.spv.
# The include root holds Packages/<package name> -> package root, so Unity-style includes
# ("Packages/com.softbodydynamics.dots/Shaders/Kernels/X.hlsl") resolve.
# CI_GLSLANG=1 is defined, so kernels can work around glslang bugs (see
# shared/reference/gpu-testing.md: WavePrefixSum is inclusive under glslang 12).
#
# Output: one "PASS file:kernel" or "FAIL file:kernel" line per kernel (a FAIL is followed
# by the tool's text, indented), and as the last line exactly one
#   RESULT shadercheck <passed> <failed>        (or RESULT shadercheck-selftest <met> <unmet>)
# Exit status: 0 when nothing failed, 1 when something failed, 2 for a usage or setup error.
set -euo pipefail

SCRIPT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
PKG_ROOT="$(cd "$SCRIPT_DIR/../.." && pwd)"
FIXTURES_DIR="$SCRIPT_DIR/fixtures"
TARGET_ENV="vulkan1.1"

usage() {
    sed -n '2,8p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
}

MODE="check"
case "${1:-}" in
    "") ;;
    --self-test) MODE="selftest" ;;
    -h|--help) usage; exit 0 ;;
    *) echo "shader-check: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
esac
RESULT_TAG="shadercheck"
[[ "$MODE" == "selftest" ]] && RESULT_TAG="shadercheck-selftest"

# ---------------------------------------------------------------------------------------
# Tools
# ---------------------------------------------------------------------------------------
missing=()
command -v glslangValidator >/dev/null 2>&1 || missing+=("glslangValidator (Debian package: glslang-tools)")
command -v spirv-val >/dev/null 2>&1 || missing+=("spirv-val (Debian package: spirv-tools)")
command -v spirv-dis >/dev/null 2>&1 || missing+=("spirv-dis (Debian package: spirv-tools)")
command -v perl >/dev/null 2>&1 || missing+=("perl (Debian package: perl-base)")
if ((${#missing[@]} > 0)); then
    echo "shader-check: ERROR: required tools not found:" >&2
    for m in "${missing[@]}"; do echo "  - $m" >&2; done
    echo "shader-check: install them with: apt-get install -y glslang-tools spirv-tools" >&2
    echo "RESULT $RESULT_TAG 0 1"
    exit 2
fi

WORK="$(mktemp -d "${TMPDIR:-/tmp}/shadercheck.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

# Include root with Packages/<name> -> package root, for Unity-style absolute includes.
PKG_NAME="$(sed -n 's/^[[:space:]]*"name"[[:space:]]*:[[:space:]]*"\([^"]*\)".*/\1/p' "$PKG_ROOT/package.json" 2>/dev/null | head -n1 || true)"
INC_ROOT="$WORK/include-root"
mkdir -p "$INC_ROOT/Packages"
if [[ -n "$PKG_NAME" ]]; then
    ln -s "$PKG_ROOT" "$INC_ROOT/Packages/$PKG_NAME"
fi

# ---------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------

# list_compute_files ROOT: every *.compute under ROOT, skipping "*~" and ".*" folders.
list_compute_files() {
    find "$1" -mindepth 1 \( -type d \( -name '*~' -o -name '.*' \) \) -prune \
        -o -type f -name '*.compute' -print | LC_ALL=C sort
}

# list_kernels FILE: one line per "#pragma kernel" (not commented out with // or inside a
# /* */ block): "NAME DEF1 DEF2=v ...".
list_kernels() {
    awk '
        {
            line = $0
            # drop /* ... */ comments, including ones that span lines
            out = ""
            while (length(line) > 0) {
                if (inblock) {
                    e = index(line, "*/")
                    if (e == 0) { line = ""; break }
                    line = substr(line, e + 2); inblock = 0
                } else {
                    s = index(line, "/*"); c = index(line, "//")
                    if (c > 0 && (s == 0 || c < s)) { out = out substr(line, 1, c - 1); line = ""; break }
                    if (s == 0) { out = out line; line = ""; break }
                    out = out substr(line, 1, s - 1); line = substr(line, s + 2); inblock = 1
                }
            }
            if (out ~ /^[ \t]*#[ \t]*pragma[ \t]+kernel[ \t]+[A-Za-z_][A-Za-z0-9_]*/) {
                sub(/^[ \t]*#[ \t]*pragma[ \t]+kernel[ \t]+/, "", out)
                gsub(/[ \t\r]+/, " ", out); sub(/ $/, "", out)
                print out
            }
        }' "$1"
}

# relpath FILE: FILE relative to the package root (or to the fixtures folder's parent).
relpath() {
    local f="$1"
    case "$f" in
        "$PKG_ROOT"/*) printf '%s' "${f#"$PKG_ROOT"/}" ;;
        *) printf '%s' "$f" ;;
    esac
}

LAST_ERROR=""
KERNEL_SEQ=0

# check_kernel FILE KERNEL [DEFINES...]: compile + validate one kernel.
# Returns 0 on success; on failure returns 1 and leaves the tool text in LAST_ERROR.
check_kernel() {
    local file="$1" kernel="$2"; shift 2
    local dir; dir="$(dirname "$file")"
    KERNEL_SEQ=$((KERNEL_SEQ + 1))
    local spv="$WORK/k$KERNEL_SEQ.spv"
    local defs=(-DCI_GLSLANG=1)
    local d
    for d in "$@"; do
        [[ -n "$d" ]] && defs+=("-D$d")
    done

    local out rc=0
    out="$(glslangValidator -D -V -S comp -e "$kernel" --amb --target-env "$TARGET_ENV" \
            -I"$INC_ROOT" -I"$PKG_ROOT" -I"$dir" "${defs[@]}" \
            -o "$spv" "$file" 2>&1)" || rc=$?
    if ((rc != 0)); then
        LAST_ERROR="glslangValidator exit code $rc"$'\n'"$out"
        return 1
    fi
    if grep -q -i "Entry point not found" <<<"$out"; then
        LAST_ERROR="glslangValidator: entry point '$kernel' not found"$'\n'"$out"
        return 1
    fi
    if grep -q "ERROR" <<<"$out"; then
        LAST_ERROR="glslangValidator reported an error"$'\n'"$out"
        return 1
    fi
    if [[ ! -s "$spv" ]]; then
        LAST_ERROR="glslangValidator wrote no SPIR-V"$'\n'"$out"
        return 1
    fi
    # Unity (FXC/DXC) rejects a kernel without [numthreads]; glslang silently uses 1,1,1.
    # Look for the attribute in the preprocessed source (includes inlined, macros expanded).
    local pre
    if ! pre="$(glslangValidator -D -E -S comp -e "$kernel" \
            -I"$INC_ROOT" -I"$PKG_ROOT" -I"$dir" "${defs[@]}" "$file" 2>&1)"; then
        LAST_ERROR="glslangValidator -E (preprocess) failed"$'\n'"$pre"
        return 1
    fi
    if ! KERNEL="$kernel" perl -0777 -ne \
        'exit(/numthreads\s*\([^)]*\)\s*\]\s*(?:\[[^\]]*\]\s*)*void\s+\Q$ENV{KERNEL}\E\s*\(/ ? 0 : 1)' \
        <<<"$pre"; then
        LAST_ERROR="kernel '$kernel' has no [numthreads(x,y,z)] attribute (Unity requires one; glslang would silently use 1,1,1)"
        return 1
    fi
    local dis
    if ! dis="$(spirv-dis "$spv" 2>&1)"; then
        LAST_ERROR="spirv-dis failed"$'\n'"$dis"
        return 1
    fi
    if ! grep -q -E "OpEntryPoint GLCompute %[^ ]+ \"$kernel\"" <<<"$dis"; then
        LAST_ERROR="SPIR-V has no GLCompute entry point \"$kernel\""$'\n'"$(grep OpEntryPoint <<<"$dis" || true)"$'\n'"$out"
        return 1
    fi
    local val
    if ! val="$(spirv-val --target-env "$TARGET_ENV" "$spv" 2>&1)"; then
        LAST_ERROR="spirv-val --target-env $TARGET_ENV failed"$'\n'"$val"
        return 1
    fi
    LAST_ERROR=""
    return 0
}

print_indented() {
    # shellcheck disable=SC2001
    sed -e '/^[[:space:]]*$/d' -e 's/^/    /' <<<"$1"
}

# check_file FILE: check every kernel of FILE, print PASS/FAIL lines.
# Sets FILE_PASSED / FILE_FAILED / FILE_KERNELS.
check_file() {
    local file="$1" rel; rel="$(relpath "$file")"
    FILE_PASSED=0; FILE_FAILED=0; FILE_KERNELS=0
    local spec
    local -a kernels=()
    mapfile -t kernels < <(list_kernels "$file")
    if ((${#kernels[@]} == 0)); then
        echo "NOTE $rel: no #pragma kernel lines"
        return 0
    fi
    for spec in "${kernels[@]}"; do
        local -a parts
        read -r -a parts <<<"$spec"
        local name="${parts[0]}"
        FILE_KERNELS=$((FILE_KERNELS + 1))
        if check_kernel "$file" "$name" "${parts[@]:1}"; then
            echo "PASS $rel:$name"
            FILE_PASSED=$((FILE_PASSED + 1))
        else
            echo "FAIL $rel:$name"
            print_indented "$LAST_ERROR"
            FILE_FAILED=$((FILE_FAILED + 1))
        fi
    done
}

START_NS="$(date +%s%N)"
elapsed() {
    local now; now="$(date +%s%N)"
    awk -v a="$START_NS" -v b="$now" 'BEGIN { printf "%.2f", (b - a) / 1e9 }'
}

# ---------------------------------------------------------------------------------------
# Self-test: every fixture states "// shadercheck-expect: pass" or "... fail".
# A fixture passes when it has at least one kernel and all its kernels pass.
# ---------------------------------------------------------------------------------------
if [[ "$MODE" == "selftest" ]]; then
    met=0; unmet=0
    mapfile -t fixtures < <(find "$FIXTURES_DIR" -maxdepth 1 -type f -name '*.compute' | LC_ALL=C sort)
    if ((${#fixtures[@]} == 0)); then
        echo "shader-check self-test: no fixtures in $FIXTURES_DIR"
        echo "RESULT $RESULT_TAG 0 1"
        exit 1
    fi
    for f in "${fixtures[@]}"; do
        expect="$(sed -n 's/.*shadercheck-expect:[[:space:]]*\([a-z]*\).*/\1/p' "$f" | head -n1)"
        if [[ "$expect" != "pass" && "$expect" != "fail" ]]; then
            echo "SELFTEST-UNMET $(basename "$f"): no '// shadercheck-expect: pass|fail' line"
            unmet=$((unmet + 1))
            continue
        fi
        check_file "$f"
        if ((FILE_KERNELS > 0 && FILE_FAILED == 0)); then got="pass"; else got="fail"; fi
        if [[ "$got" == "$expect" ]]; then
            echo "SELFTEST-MET $(basename "$f"): expected $expect, got $got"
            met=$((met + 1))
        else
            echo "SELFTEST-UNMET $(basename "$f"): expected $expect, got $got"
            unmet=$((unmet + 1))
        fi
    done
    echo "shader-check self-test: ${#fixtures[@]} fixtures in $(elapsed)s ($(glslangValidator --version 2>/dev/null | head -n1), $(spirv-val --version 2>/dev/null | head -n1 | cut -d' ' -f1-2))"
    echo "RESULT $RESULT_TAG $met $unmet"
    if ((unmet > 0)); then exit 1; fi
    exit 0
fi

# ---------------------------------------------------------------------------------------
# Normal mode
# ---------------------------------------------------------------------------------------
passed=0; failed=0; nfiles=0
mapfile -t files < <(list_compute_files "$PKG_ROOT")
for f in "${files[@]}"; do
    [[ -z "$f" ]] && continue
    nfiles=$((nfiles + 1))
    check_file "$f"
    passed=$((passed + FILE_PASSED)); failed=$((failed + FILE_FAILED))
done
echo "shader-check: found $((passed + failed)) kernels in $nfiles .compute files under $PKG_ROOT ($(elapsed)s)"
echo "RESULT $RESULT_TAG $passed $failed"
((failed == 0)) || exit 1

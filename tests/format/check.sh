#!/usr/bin/env bash
# check.sh REPO: every C++ file of the project is as clang-format leaves it (.clang-format: Google
# style, 100 columns), so the format applied once (issue 33, item 6) stays. Lists each file that
# differs and the first lines clang-format would change; fix with
#   clang-format -i $(git ls-files '*.cpp' '*.hpp' '*.h')
# The version is Debian bookworm's clang-format 14 (setup.sh): another version may format
# differently, so the test names the one it ran.
set -uo pipefail
repo=$1
cd "$repo" || exit 1
command -v clang-format >/dev/null || { echo "check.sh: no clang-format (setup.sh installs it)"; exit 1; }
echo "$(clang-format --version)"
mapfile -t files < <(find src tests bench -name '*.cpp' -o -name '*.hpp' -o -name '*.h' | sort)
[ "${#files[@]}" -gt 400 ] || { echo "check.sh: only ${#files[@]} C++ files found under $repo"; exit 1; }
# one clang-format for all files (one process per file took 15 s)
out=$(clang-format --dry-run "${files[@]}" 2>&1)
bad=$(grep -oE '^[^:]+\.(cpp|hpp|h):[0-9]+:[0-9]+: warning' <<<"$out" | cut -d: -f1 | sort -u | wc -l)
[ "$bad" -gt 0 ] && grep -E ': warning' <<<"$out" | head -n 20
echo "check.sh: ${#files[@]} files, $bad not formatted"
[ "$bad" -eq 0 ]

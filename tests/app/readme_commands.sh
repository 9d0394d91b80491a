#!/usr/bin/env bash
# readme_commands.sh IWB REPO SCRATCH: the README's promises about the command line, read from
# README.md at test time so that neither can drift from the other:
#   - every command of the "## What is here" table answers --help with exit 0, and its help names
#     every option the row names;
#   - the quick ones (QUICK below, each a row of that table) run for real and exit 0;
#   - the setup block: setup.sh is executable, `build/iwb X` is a command, and the ctest line is
#     exactly the one .ci/run runs.
set -uo pipefail
iwb=$1; repo=$2; scratch=$3
mkdir -p "$scratch"
readme=$repo/README.md
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The first cell of each row of the first table under "## What is here", `\|` unescaped.
table_commands() {
  # shellcheck disable=SC2016  # the backticks are markdown, not shell
  sed -n '/^## What is here/,/^## /p' "$readme" | awk '/^\|/ {t = 1} t && !/^\|/ {exit} t' |
    grep -E '^\| `iwb ' | sed -E 's/^\| `([^`]*)`.*/\1/; s/\\\|/|/g'
}

# The subcommand words of a command line: the lowercase words after `iwb`, up to the first
# argument, placeholder or option ("iwb dem run SCENE.toml --np N" -> "dem run").
subcommand_of() {
  local words=() w
  for w in $1; do
    [ "$w" = iwb ] && continue
    [[ $w =~ ^[a-z][a-z0-9-]*$ ]] || break
    words+=("$w")
  done
  echo "${words[*]}"
}

# The options a command line names: -o, --out, --engine ... (not the values after them).
options_of() { grep -oE '(^|[ [])--?[a-zA-Z][a-zA-Z0-9-]*' <<<"$1" | sed -E 's/^[ []//' | sort -u; }

check_help() {
  local row=$1 sub help opt
  sub=$(subcommand_of "$row")
  [ -n "$sub" ] || { fail "no subcommand in README row '$row'"; return; }
  # shellcheck disable=SC2086  # sub is a list of words
  help=$("$iwb" $sub --help 2>&1) || { fail "'iwb $sub --help' exits $?"; return; }
  for opt in $(options_of "$row"); do
    grep -Eq -- "(^|[ ,])$opt([ ,=]|$)" <<<"$help" ||
      fail "README row '$row' names $opt, which 'iwb $sub --help' does not list"
  done
  echo "ok: iwb $sub --help lists $(options_of "$row" | tr '\n' ' ')"
}

rows=$(table_commands)
[ "$(wc -l <<<"$rows")" -ge 10 ] || fail "README.md: fewer than 10 commands in the '## What is here' table"
while IFS= read -r row; do check_help "$row"; done <<<"$rows"

# Where a command run here writes: the scratch directory, never the repository.
out_option() {
  case $1 in
    element | compare) echo "--out $scratch/try-${1// /-} --force" ;;
  esac
}

# Quick commands run for real: each must be a command of the table (so this list cannot outlive it).
# (`bench element` runs in its own two tests of tests/CMakeLists.txt: not a third time here.)
QUICK=(
  "models"
  "element $repo/data/tests/hvwe_cnl_dense.toml --out $scratch/element --force"
)
for q in "${QUICK[@]}"; do
  sub=$(subcommand_of "iwb $q")
  grep -qxE "iwb $sub( .*)?" <<<"$rows" || fail "'iwb $sub' runs here but is not in README's table"
  # shellcheck disable=SC2086  # q is a command line
  (cd "$repo" && "$iwb" $q >"$scratch/quick.log" 2>&1) || { fail "'iwb $q' exits $?"; cat "$scratch/quick.log"; }
  echo "ok: iwb $q"
done

# The first page's "Try first" table: every command is one (`--help`), and those that take a
# second or less run for real from the repository and exit 0.
try_first=$(awk '/^Try first/ {t = 1; next} t && /^\| `build\/iwb / {print} t && /^$/ && n++ > 0 {exit}' "$readme")
[ -n "$try_first" ] || fail "README.md: no 'Try first' table of build/iwb commands"
while IFS= read -r row; do
  line=$(sed -E 's/^\| `build\/iwb ([^`]*)`.*/\1/' <<<"$row")
  sub=$(subcommand_of "iwb $line")
  # shellcheck disable=SC2086  # sub is a list of words
  "$iwb" $sub --help >/dev/null 2>&1 || { fail "README's 'Try first' names 'iwb $sub', which is no command"; continue; }
  if grep -Eq '\| (instant|under a second|a second) \|$' <<<"$row"; then
    # shellcheck disable=SC2086  # line is a command line; its outputs go to the scratch directory
    (cd "$repo" && "$iwb" $line $(out_option "$sub") >"$scratch/try.log" 2>&1) ||
      { fail "README's 'Try first' 'iwb $line' exits $?"; cat "$scratch/try.log"; }
    echo "ok: try first: iwb $line"
  fi
done <<<"$try_first"

# The setup block: the first ```sh block of the README.
setup=$(awk '/^```sh/ {b = 1; next} b && /^```/ {exit} b' "$readme")
grep -qx './setup.sh' <<<"$setup" || fail "README's setup block does not run ./setup.sh"
[ -x "$repo/setup.sh" ] || fail "setup.sh is not executable"
while read -r _ sub; do
  # shellcheck disable=SC2086
  "$iwb" $sub --help >/dev/null 2>&1 || fail "README's setup block runs 'build/iwb $sub', which is no command"
done < <(grep -E '^build/iwb ' <<<"$setup")
ctest_line=$(grep -E '^ctest ' <<<"$setup")
[ -n "$ctest_line" ] || fail "README's setup block has no ctest line"
grep -qxF -- "$ctest_line" "$repo/.ci/run" || fail "README's '$ctest_line' is not the line .ci/run runs"
echo "ok: setup block (./setup.sh, $ctest_line)"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }

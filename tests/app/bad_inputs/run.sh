#!/usr/bin/env bash
# run.sh IWB REPO SCRATCH CASES...: the bad-input corpus (tests/README.md, "Bad-input corpus").
# Each case of each CASES file runs in a fresh directory SCRATCH/<file>/<case>: its inputs are
# made there, the directory is listed, iwb runs there, and the case passes if iwb exits 2, its
# stderr matches the case's regex (naming the file, key and value, or the option and value),
# its stdout is empty, and the directory lists exactly as before (nothing written, not even a
# temporary file). Prints one line per case and every failure in full; exits 1 if any failed.
# CASE_TIMEOUT (s, default 60) stops a case that was not refused (exit 124).
#
# A case is a block of lines (blank lines and lines starting with # between blocks are ignored):
#   case NAME: what is wrong       starts a case
#   copy SRC DST                   copy a file or directory (SRC relative to REPO's data/)
#   set FILE TABLE.KEY VALUE       set KEY = VALUE in [TABLE] of a TOML file (KEY alone: top level;
#                                  the line is replaced, or added to the table, or the table added)
#   drop FILE TABLE.KEY            remove the key's line
#   write FILE TEXT                write TEXT (printf %b: \n is a newline) to FILE
#   truncate FILE BYTES            cut FILE to its first BYTES bytes
#   sed FILE EXPR                  edit FILE in place with sed -E EXPR (JSON and CSV files)
#   mkdir DIR                      make a directory
#   symlink TARGET LINK            make a symbolic link LINK -> TARGET (a loop: TARGET = LINK)
#   fifo FILE                      make a named pipe
#   run ARGS...                    iwb's arguments (shell words)
# $DATA in any line is REPO/data.
#   expect REGEX                   extended regex the stderr must match
set -u
IWB=$1 REPO=$2 SCRATCH=$3
shift 3
export DATA=$REPO/data
passed=0 failed=0 failures=""

toml_set() {  # file table key value (value empty and mode=drop: remove)
  local file=$1 table=$2 key=$3 value=$4 mode=${5:-set}
  awk -v table="$table" -v key="$key" -v value="$value" -v mode="$mode" '
    function flush() { if (inside && !done && mode == "set") print key " = " value; done = 1 }
    BEGIN { inside = (table == "") }
    /^[ \t]*\[/ { if (inside) flush(); inside = ($0 ~ "^[ \t]*\\[" table "\\][ \t]*$"); print; next }
    inside && $0 ~ "^[ \t]*" key "[ \t]*=" { if (mode == "set") print key " = " value; done = 1; next }
    { print }
    END { if (inside) flush(); if (!done && mode == "set") { print "[" table "]"; print key " = " value } }
  ' "$file" > "$file.new" && mv "$file.new" "$file"
}

# In directory order, unsorted: an unchanged directory reads back in the same order, and a sort
# cost a fork per listing (the corpus is ~500 cases; forks were most of its time).
listing() { find . -printf '%p %s %T@\n'; }

run_case() {  # name, then the case's lines in the global array LINES
  local name=$1 dir=$2 args=() regex="" line cmd a b rest
  mkdir -p "$dir" && cd "$dir" || return 1
  for line in "${LINES[@]}"; do
    read -r cmd rest <<<"$line"
    rest=${rest//\$DATA/$DATA}
    case $cmd in
      copy) read -r a b <<<"$rest"; cp -r "$DATA/$a" "$b" ;;
      set | drop)
        read -r a b rest <<<"$rest"
        local table=${b%.*} key=${b##*.}
        [ "$table" = "$b" ] && table=""
        toml_set "$a" "$table" "$key" "$rest" "$cmd" ;;
      write) read -r a rest <<<"$rest"; printf '%b' "$rest" > "$a" ;;
      truncate) read -r a b <<<"$rest"; truncate -s "$b" "$a" ;;
      sed) read -r a b <<<"$rest"; sed -E -i "$b" "$a" ;;
      mkdir) mkdir -p "$rest" ;;
      symlink) read -r a b <<<"$rest"; ln -s "$a" "$b" ;;
      fifo) mkfifo "$rest" ;;
      run) eval "args=($rest)" ;;
      expect) regex=$rest ;;
      *) echo "bad directive in case $name: $line"; return 1 ;;
    esac
  done
  local before after code
  before=$(listing)
  # beside the directory, not in it; a case that is not refused must not run an engine for long
  timeout "${CASE_TIMEOUT:-60}" "$IWB" "${args[@]}" >"$dir.stdout" 2>"$dir.stderr"
  code=$?
  local out err
  IFS= read -r -d '' out <"$dir.stdout"
  IFS= read -r -d '' err <"$dir.stderr"
  after=$(listing)
  local why=""
  [ "$code" -eq 2 ] || why+="exit code $code, expected 2; "
  grep -Eq -- "$regex" <<<"$err" || why+="stderr does not match /$regex/; "
  [ -z "$out" ] || why+="stdout is not empty; "
  [ "$before" = "$after" ] || why+="the directory changed: $(diff <(echo "$before") <(echo "$after") | grep '^[<>]' | head -5 | tr '\n' ' '); "
  if [ -z "$why" ]; then
    echo "ok   $name"
    return 0
  fi
  echo "FAIL $name: $why"
  echo "     iwb ${args[*]}"
  echo "     stderr: $err"
  [ -z "$out" ] || echo "     stdout: $out"
  return 1
}

for cases in "$@"; do
  group=$(basename "$cases" .cases)
  rm -rf "${SCRATCH:?}/$group"  # each case's directory fresh, one removal for the group
  name="" LINES=()
  finish() {
    [ -n "$name" ] || return 0
    if (run_case "$name" "$SCRATCH/$group/${name%%:*}"); then passed=$((passed + 1))
    else failed=$((failed + 1)); failures+=" ${name%%:*}"; fi
  }
  while IFS= read -r line || [ -n "$line" ]; do
    case $line in
      "case "*) finish; name=${line#case }; LINES=() ;;
      "" | "#"*) ;;
      *) LINES+=("$line") ;;
    esac
  done <"$cases"
  finish
done
echo "$passed passed, $failed failed${failures:+:$failures}"
[ "$failed" -eq 0 ]

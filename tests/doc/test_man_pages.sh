#!/usr/bin/env bash
# The man pages: shadelab(1) and a shadelab-COMMAND(1) for every command
# that `shadelab --help` lists; each renders through man without a warning
# from groff, is titled and named after itself, and shows every option of
# its command's --help.
#   test_man_pages.sh SHADELAB PAGES_DIR
set -uo pipefail
shadelab=$1
pages=$2
source "$(dirname "$0")/help_text.sh"
export LC_ALL=C.UTF-8
failed=0
fail() {
  echo "FAIL: $*" >&2
  failed=1
}

# check_page PAGE [COMMAND]
check_page() {
  local page=$1 file=$pages/$1.1 warnings text option
  shift
  if [[ ! -f $file ]]; then
    fail "$file is missing"
    return
  fi
  # -ww: every warning groff has; -z: no output but the warnings.
  warnings=$(groff -man -Tutf8 -ww -z "$file" 2>&1)
  [[ -z $warnings ]] || fail "$page: groff warns: $warnings"
  # Wide, so that no option is hyphenated across lines.
  text=$(MANWIDTH=250 man --warnings -l "$file" 2>&1) || fail "$page: man -l failed"
  [[ $(head -n 1 <<<"$text") == "${page^^}(1)"* ]] || fail "$page: title is $(head -n 1 <<<"$text")"
  grep -qE "^ +$page - " <<<"$text" || fail "$page: no NAME line '$page - ...'"
  grep -qE "^ +shadelab $*" <<<"$text" || fail "$page: no synopsis 'shadelab $*'"
  while read -r option; do
    grep -qE -- "(^|[ ,])$option([ ,]|$)" <<<"$text" || fail "$page: option $option of --help is missing"
  done < <(help_options "$shadelab" "$@")
}

check_page shadelab
commands=$(help_commands "$shadelab")
[[ -n $commands ]] || fail "shadelab --help lists no commands"
for command in $commands; do
  check_page "shadelab-$command" "$command"
  grep -qF ".BR shadelab-$command (1)" "$pages/shadelab.1" ||
    fail "shadelab(1) does not name shadelab-$command(1) in SEE ALSO"
done
# No page for a command that is not there any more.
for file in "$pages"/shadelab-*.1; do
  command=${file##*/shadelab-}
  grep -qx "${command%.1}" <<<"$commands" || fail "$file: no such command in shadelab --help"
done
exit $failed

#!/usr/bin/env bash
# The option reference (doc/user/options.md) and every command's --help list
# the same options: a setting's heading names the commands that take it, a
# command's own options have headings under the command.
# Usage: test_option_reference.sh SHADELAB REFERENCE.md
set -euo pipefail
shadelab=$1
reference=$2
source "$(dirname "$0")/help_text.sh"

# The option names the reference gives command $1.
reference_options() {
  awk -v command="$1" '
    /^## / { section = $2 }
    /^### / { heading = substr($0, 5) }
    section == "Settings" && /^- Commands: / {
      n = split(substr($0, 13), taken, ", ")
      for (i = 1; i <= n; i++) if (taken[i] == command) print heading
    }
    section == command && /^### / {
      n = split(substr(heading, length(command) + 2), names, ", ")
      for (i = 1; i <= n; i++) if (names[i] ~ /^-/) print names[i]
    }' "$reference"
}

failed=0
for command in $(help_commands "$shadelab"); do
  help=$(help_options "$shadelab" "$command" | grep -vx -- '-h\|--help' | sort)
  documented=$(reference_options "$command" | sort)
  if [[ -z $help ]]; then
    echo "FAIL: $command --help lists no options"
    failed=1
  elif [[ $help != "$documented" ]]; then
    echo "FAIL: $command: --help and $reference differ (<: --help only, >: the reference only):"
    diff <(echo "$help") <(echo "$documented") | grep '^[<>]' || true
    failed=1
  else
    echo "ok: $command: $(echo "$help" | wc -l) options"
  fi
done
exit $failed

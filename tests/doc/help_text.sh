# shellcheck shell=bash
# What the doc tests read from shadelab's --help, sourced by them.

# The commands that `shadelab --help` lists.
help_commands() {
  "$1" --help | awk '/^Subcommands:/ { l = 1; next } /^[^ ]/ { l = 0 } l && /^  [a-z]/ { print $1 }'
}

# Every option name (short and long) that `shadelab [COMMAND] --help` lists.
help_options() {
  "$@" --help | awk '/^Options:/ { l = 1; next } /^[^ ]/ { l = 0 } l && /^  -/ { print $1 }' | tr ',' '\n'
}

# shellcheck shell=bash
# Shared by the benchmark scripts (sourced, not run): messages, Debian
# packages, an Xvfb server for the tools that need a display, waiting for a
# quiet machine, the machine and its load for the reports, timing a process,
# shadelab's phase lines, medians, the meshes folder and quoting. The
# sourcing script sets bench_name first.
: "${bench_name:?set bench_name before sourcing bench-common.sh}"

# The folder of shadelab-bench-meshes' meshes that every script shares (the
# 17.8M bunny takes minutes to make): made once, kept between runs.
# shellcheck disable=SC2034 # for the sourcing scripts
bench_meshes=${BENCH_MESHES:-out/bench-meshes}

die() {
  echo "$bench_name: error: $*" >&2
  exit 1
}

note() { echo "$bench_name: $*" >&2; }

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q '^install ok installed$'; }

# ensure_packages PACKAGE...: installs the missing ones from Debian's archive
# (--no-remove: never takes a package away).
ensure_packages() {
  local sudo="" missing=() p
  [[ $(id -u) -eq 0 ]] || sudo="sudo"
  for p in "$@"; do
    installed "$p" || missing+=("$p")
  done
  if ((${#missing[@]})); then
    note "installing: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends --no-remove "${missing[@]}" >&2
  fi
}

# start_xvfb LOG: starts Xvfb on the first free display from 97 (or
# $BENCH_DISPLAY), waits until it answers, and sets xdisplay and xvfb_pid.
# The caller kills it on exit.
start_xvfb() {
  local log=$1 display_num i
  if [[ -n ${BENCH_DISPLAY:-} ]]; then
    display_num=$BENCH_DISPLAY
  else
    display_num=97
    while [[ -e /tmp/.X$display_num-lock || -e /tmp/.X11-unix/X$display_num ]]; do
      display_num=$((display_num + 1))
    done
  fi
  xdisplay=:$display_num
  # -noreset: no server reset between clients, which a client arriving just
  # then can see as a refused connection.
  Xvfb "$xdisplay" -screen 0 1920x1080x24 -nolisten tcp -noreset >"$log" 2>&1 &
  xvfb_pid=$!
  for ((i = 0; ; i++)); do
    xdpyinfo -display "$xdisplay" >/dev/null 2>&1 && break
    kill -0 "$xvfb_pid" 2>/dev/null || die "Xvfb $xdisplay exited; see $log"
    ((i < 200)) || die "Xvfb $xdisplay did not answer within 10 s"
    sleep 0.05
  done
}

cpu_ticks() { # prints "busy idle" from /proc/stat's cpu line
  awk '/^cpu / { idle = $5 + $6; busy = 0; for (i = 2; i <= NF; i++) busy += $i; print busy - idle, idle }' /proc/stat
}

settle() { # until the CPUs are 90% idle over 0.2 s and no orted is left, at most 5 s
  local i b0 i0 b1 i1
  for ((i = 0; i < 25; i++)); do
    read -r b0 i0 < <(cpu_ticks)
    sleep 0.2
    read -r b1 i1 < <(cpu_ticks)
    if ((10 * (b1 - b0) <= (b1 - b0) + (i1 - i0))) && ! pgrep -x orted >/dev/null; then
      return
    fi
  done
}

first_line() { # first line of a command's output, or "?" if it fails
  local o
  o=$(timeout 60 "$@" 2>&1 </dev/null) || { echo "? (\`$*\` failed)"; return; }
  echo "${o%%$'\n'*}"
}

quote_cmd() { # the command as one shell-quoted line
  local out="" w
  for w in "$@"; do
    if [[ $w =~ ^[A-Za-z0-9_./:=,+%@-]+$ ]]; then
      out+="${out:+ }$w"
    else
      out+="${out:+ }$(printf '%q' "$w")"
    fi
  done
  echo "$out"
}

machine_line() { # the CPU model, its cores and the memory, for a report
  printf '%s, %s CPUs, %s GiB memory\n' \
    "$(awk -F': ' '/^model name/ { print $2; exit }' /proc/cpuinfo)" "$(nproc)" \
    "$(awk '/^MemTotal:/ { printf "%.0f", $2 / 1048576 }' /proc/meminfo)"
}

load_average() { cut -d' ' -f1-3 /proc/loadavg; } # over 1, 5 and 15 minutes

# timed_run LOG CMD...: runs CMD, its output (stdout and stderr) into LOG,
# under GNU time; sets wall_s (seconds) and peak_kib (the maximum resident
# set). Returns CMD's failure.
# shellcheck disable=SC2034 # wall_s and peak_kib are for the caller
timed_run() {
  local log=$1 times
  shift
  times=$(mktemp "${TMPDIR:-/tmp}/$bench_name-time.XXXXXX")
  if ! /usr/bin/time -f '%e %M' -o "$times" "$@" >"$log" 2>&1 </dev/null; then
    rm -f "$times"
    return 1
  fi
  read -r wall_s peak_kib <"$times"
  rm -f "$times"
}

# phase_lines LOG: "PHASE MS PEAK_MIB" for each phase line of LOG, as
# shadelab -v and the benchmark executables print them ("NAME: PHASE MS ms,
# peak MIB MiB"; PEAK_MIB empty where a line has no peak).
phase_lines() {
  sed -nE 's/^[a-z-]+: ([a-z]+) ([0-9.]+) ms(, peak ([0-9.]+) MiB)?$/\1 \2 \4/p' "$1"
}

median() { # of the numbers on stdin, one a line; of an even count, the mean of the middle two
  sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

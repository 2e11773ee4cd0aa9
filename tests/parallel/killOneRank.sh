#!/bin/sh
# Kills (SIGKILL) one solidtex process whose command line holds PATTERN, once two of them have
# run for two seconds: a rank of an mpirun job dying mid-work. Gives up after 30 s.
pattern=$1
ranks() {
  for pid in $(pgrep -f "$pattern"); do
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = solidtex ] && echo "$pid"
  done
}
tries=0
until [ "$(ranks | wc -l)" -ge 2 ]; do
  tries=$((tries + 1))
  [ "$tries" -gt 150 ] && exit 1
  sleep 0.2
done
sleep 2
kill -KILL "$(ranks | tail -n 1)"

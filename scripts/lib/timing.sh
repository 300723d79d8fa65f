# Sourced by scripts/build.sh, demo.sh and test.sh: how long a part took.
#   start=$(clock); ...; echo "built in $(since "$start")"     ->  "built in 3 min 05 s"

clock() { date +%s; }

# "42 s", "3 min 05 s", "1 h 02 min".
duration() {
  local s=$1
  if [ "$s" -lt 60 ]; then
    printf '%d s' "$s"
  elif [ "$s" -lt 3600 ]; then
    printf '%d min %02d s' $((s / 60)) $((s % 60))
  else
    printf '%d h %02d min' $((s / 3600)) $((s % 3600 / 60))
  fi
}

since() { duration $(($(clock) - $1)); }

#!/usr/bin/env bash
# What a new user met with demctl (issue 34), against a dem_server process
# on loopback: a server name given wrong or not at all lists the servers
# there are; a case path that is a directory or missing says so (exit 2);
# monitor's CSV columns are the case's, in one order whatever --wall
# says; and run-programme --wait's bar shows the stage and how far its
# stop condition is, not the share of millions of cycles of caps.
#   demctl_usability.sh DEM_SERVER DEMCTL CASES_DIR OUT_DIR DOMAIN EMPTY_DOMAIN
# (EMPTY_DOMAIN: one no server of the suite uses.)
set -uo pipefail
server_program=$1 demctl=$2 cases=$3 out=$4 domain=$5 empty_domain=$6
rm -rf "$out" && mkdir -p "$out"
server=""
cleanup() { [ -z "$server" ] || kill -9 "$server" 2>/dev/null; }
trap cleanup EXIT

source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"

"$server_program" --name usable --domain "$domain" --out "$out/server" --threads 1 --telemetry-cycles 100 \
  >"$out/server.log" 2>&1 &
server=$!
d=("$demctl" --server usable --domain "$domain" --timeout 10)
expect 0 "the server is there" "${d[@]}" status

# A wrong name, and none at all (the default "dem"), list the servers seen.
expect 3 "a wrong --server" "$demctl" --server usabel --domain "$domain" --timeout 2 status
said 'no server "usabel" on DDS domain'
said "servers on DDS domain $domain: usable (name one with --server NAME or \$DEM_SERVER)"
expect 3 "no --server" env -u DEM_SERVER "$demctl" --domain "$domain" --timeout 2 status
said 'no server "dem" on DDS domain'
said "servers on DDS domain $domain: usable"
expect 3 "a domain with no server" "$demctl" --server usable --domain "$empty_domain" --timeout 1 status
said "no server is on DDS domain $empty_domain"

# Case files that cannot be read: bad arguments, with the reason.
expect 2 "load DIRECTORY" "${d[@]}" load "$cases/ball"
said "cannot read $cases/ball: it is a directory, not a file"
expect 2 "load MISSING" "${d[@]}" load "$out/nothing.case.txtpb"
said "cannot read $out/nothing.case.txtpb: No such file or directory"
expect 2 "snapshot load MISSING" "${d[@]}" snapshot load "$out/nothing.snapshot"
said "cannot read $out/nothing.snapshot: No such file or directory"

# The monitor's columns: the server's walls in its order, then the
# statistics, whatever order --wall names the plates in.
expect 0 "load" "${d[@]}" load "$cases/ball/nine_disc_damped.case.txtpb"
expect 0 "cycle" "${d[@]}" cycle 300 --wait --quiet
expect 0 "monitor --wall top --wall bottom" "${d[@]}" monitor -n 2 --wall top --wall bottom --csv "$out/a.csv"
expect 0 "monitor --wall bottom --wall top" "${d[@]}" monitor -n 2 --wall bottom --wall top --csv "$out/b.csv"
columns="cycle,time,bottom_stress,bottom_settlement,top_stress,top_settlement,contacts,coordination_number"
columns+=",sliding_fraction,mean_normal_force,max_normal_force,kinetic_energy,out_of_balance"
columns+=",kinetic_to_elastic,unbalanced_force,inertial_number,elastic_energy,mean_stress"
for file in a b; do
  header=$(head -1 "$out/$file.csv")
  [ "$header" = "$columns" ] || { : >"$out/last.out"; echo "$header" >"$out/last.err"; fail "$file.csv's columns"; }
done
[ "$(sed -n 2p "$out/a.csv")" = "$(sed -n 2p "$out/b.csv")" ] || fail "the same sample gave different rows"

# run-programme --wait at a terminal (script(1) gives it one): the bar
# names the stage and its stress against the target, and gives no time
# left (its 3 million cycles of caps are no forecast).
expect 0 "load the reduced CS" "${d[@]}" load "$cases/miyata/cs_reduced.case.txtpb"
expect 0 "the first two stages" "${d[@]}" run-programme --stages 2 --wait --quiet
script -qefc "$(printf '%q ' "${d[@]}" run-programme --from 3 --wait)" /dev/null >"$out/last.out" 2>"$out/last.err"
code=$?
[ $code -eq 0 ] && echo "ok: run-programme --wait at a terminal" || fail "run-programme --wait at a terminal: exit $code"
tr '\r' '\n' <"$out/last.out" | grep -a 'cycle' >"$out/bar.txt"
said "programme complete at cycle"
grep -aq "stage 3/3 load: top stress .* kPa of 900 kPa" "$out/bar.txt" || fail "no bar line shows the plate's stress against 900 kPa"
if grep -aq " left" "$out/bar.txt"; then fail "a programme's bar gives a time left"; fi
# Each bar's share is its stress over the 900 kPa the stage runs to.
while IFS= read -r line; do
  percent=$(sed -n 's/^\[[#-]*\] *\([0-9]*\)%.*/\1/p' <<<"$line")
  stress=$(sed -n 's/.*top stress \([0-9.e+-]*\) kPa of 900 kPa.*/\1/p' <<<"$line")
  [ -n "$percent" ] && [ -n "$stress" ] || continue
  awk -v p="$percent" -v s="$stress" 'BEGIN { f = s / 9; if (f > 100) f = 100; if (f < 0) f = 0; exit !(p - f <= 1 && f - p <= 1) }' ||
    fail "a bar shows $percent % at $stress kPa of 900"
done < <(sed 's/\x1b\[K//g' "$out/bar.txt")
echo "  the last bar: $(grep -a '%' "$out/bar.txt" | tail -1 | sed 's/\x1b\[K//')"

expect 0 "shutdown" "${d[@]}" shutdown
wait "$server"
server=""
if [ $failures -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "all passed"

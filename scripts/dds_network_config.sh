#!/usr/bin/env bash
# Writes a Cyclone DDS configuration for dem_server, demctl and the clients
# on the hosts of a real network (docs/DDS.md, "Across hosts"): one chosen
# interface, and discovery by unicast to the listed peers with multicast
# off - what works where a cluster or a cloud forbids multicast, and keeps
# DDS traffic to the hosts named. Give every process on every host the file
# made with the same peers (each host its own --interface):
#
#   dds_network_config.sh --interface eth0 --peer 192.0.2.10 --peer 192.0.2.11 > /etc/dem/cyclonedds.xml
#   export CYCLONEDDS_URI=file:///etc/dem/cyclonedds.xml
#
# Options:
#   --interface NAME|ADDRESS  the interface on the network the hosts share (by name, or this host's address on it)
#   --peer HOST               a host that runs servers or clients, this one included; repeat for each
#   --participants N          DDS participants per host (each dem_server, demctl or client process is one;
#                             a node running K sweep tasks with a monitor needs K + 1 or more); default 20
#   --multicast               discover by multicast instead (no --peer needed), where the network allows it
#
# The UDP ports to open between the hosts, for domain d and N participants
# per host, are 7400 + 250 d + 10 ... 7400 + 250 d + 11 + 2 N (a comment in
# the output lists them), and with --multicast 7400 + 250 d and 7401 + 250 d. Nothing here is encrypted or authenticated: keep
# it on a trusted network.
set -euo pipefail
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }

interface="" participants=20 multicast=false peers=()
while [ $# -gt 0 ]; do
  case "$1" in
    --interface) interface="${2:?--interface needs a value}"; shift 2 ;;
    --peer) peers+=("${2:?--peer needs a value}"); shift 2 ;;
    --participants) participants="${2:?--participants needs a value}"; shift 2 ;;
    --multicast) multicast=true; shift ;;
    -h | --help) usage ;;
    *) echo "dds_network_config: unknown argument $1" >&2; usage ;;
  esac
done
[ -n "$interface" ] || { echo "dds_network_config: give --interface" >&2; exit 2; }
[[ "$participants" =~ ^[1-9][0-9]*$ ]] && [ "$participants" -le 119 ] ||
  { echo "dds_network_config: --participants must be 1 to 119" >&2; exit 2; }
[ $multicast = true ] || [ ${#peers[@]} -gt 0 ] ||
  { echo "dds_network_config: give the hosts with --peer (or --multicast)" >&2; exit 2; }
for peer in "${peers[@]}"; do
  [[ "$peer" =~ ^[A-Za-z0-9.:_-]+$ ]] || { echo "dds_network_config: \"$peer\" is not a host name or address" >&2; exit 2; }
done
[[ "$interface" =~ ^[A-Za-z0-9.:_-]+$ ]] || { echo "dds_network_config: \"$interface\" is not an interface" >&2; exit 2; }
# An address (IPv4 dotted, or IPv6 with colons) selects by address, anything else by name.
if [[ "$interface" =~ ^[0-9.]+$ || "$interface" == *:* ]]; then
  selector="address=\"$interface\""
else
  selector="name=\"$interface\""
fi

cat <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<!-- Written by scripts/dds_network_config.sh: Cyclone DDS across hosts (docs/DDS.md).
     Interface $interface; $( [ $multicast = true ] && echo "multicast discovery" || echo "unicast discovery to ${peers[*]}, multicast off" ).
     UDP ports for domain d: 7400 + 250 d + 10 to 7400 + 250 d + $((11 + 2 * participants))
     (domain 0: 7410-$((7411 + 2 * participants))). -->
<CycloneDDS xmlns="https://cdds.io/config">
  <Domain Id="any">
    <General>
      <Interfaces>
        <NetworkInterface $selector/>
      </Interfaces>
      <AllowMulticast>$([ $multicast = true ] && echo true || echo false)</AllowMulticast>
    </General>
    <Discovery>
      <ParticipantIndex>auto</ParticipantIndex>
      <MaxAutoParticipantIndex>$participants</MaxAutoParticipantIndex>
EOF
if [ ${#peers[@]} -gt 0 ]; then
  echo "      <Peers>"
  for peer in "${peers[@]}"; do echo "        <Peer address=\"$peer\"/>"; done
  echo "      </Peers>"
fi
cat <<EOF
    </Discovery>
  </Domain>
</CycloneDDS>
EOF

#!/usr/bin/env bash
# Makes everything DDS Security needs for a test or a trial (docs/SECURITY.md):
#   OUT/ca.pem, ca_key.pem               a CA, both identity and permissions CA
#   OUT/<who>.pem, <who>_key.pem         an identity for each name given
#   OUT/governance_ca.xml(.p7s)          authentication, access control and
#                                        encryption required on domains 0-230
#   OUT/permissions_<who>.xml(.p7s)      <who> may publish and subscribe every topic
#   OUT/cyclonedds-<who>.xml             the loopback configuration with
#                                        Security for <who>: CYCLONEDDS_URI=file://...
#   OUT/other_ca.pem, intruder.pem, ...  a second CA and an identity it signed,
#                                        with its own permissions and
#                                        configuration: what must be refused
#   scripts/make_test_ca.sh OUT [NAME ...]    (default names: server client)
# Test material only: keys unencrypted, certificates valid 30 days.
set -euo pipefail
out=$1
shift || true
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(server client)
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
plugins=/usr/lib/x86_64-linux-gnu/libddsc0debian
mkdir -p "$out"
out="$(cd "$out" && pwd)"
cd "$out"
quiet() { "$@" >/dev/null 2>&1 || { echo "make_test_ca: failed: $*" >&2; "$@"; exit 1; }; }

make_ca() {  # NAME SUBJECT
  quiet openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days 30 \
    -subj "$2" -keyout "${1}_key.pem" -out "$1.pem"
}
make_identity() {  # WHO CA
  quiet openssl req -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -subj "/C=NL/O=dem test/CN=$1" \
    -keyout "${1}_key.pem" -out "$1.csr"
  quiet openssl x509 -req -in "$1.csr" -CA "$2.pem" -CAkey "${2}_key.pem" -CAcreateserial -days 30 -out "$1.pem"
  rm -f "$1.csr"
}
sign() {  # FILE CA: S/MIME, as DDS Security wants governance and permissions documents
  quiet openssl smime -sign -in "$1" -text -out "$1.p7s" -signer "$2.pem" -inkey "${2}_key.pem"
}
permissions() {  # WHO: may publish and subscribe everything on every domain
  cat >"permissions_$1.xml" <<XML
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name="$1">
      <subject_name>CN=$1,O=dem test,C=NL</subject_name>
      <validity><not_before>2020-01-01T00:00:00</not_before><not_after>2100-01-01T00:00:00</not_after></validity>
      <allow_rule>
        <domains><id_range><min>0</min><max>230</max></id_range></domains>
        <publish><topics><topic>*</topic></topics></publish>
        <subscribe><topics><topic>*</topic></topics></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
  </permissions>
</dds>
XML
}
configuration() {  # WHO CA
  cat >"cyclonedds-$1.xml" <<XML
<?xml version="1.0" encoding="UTF-8"?>
<!-- The loopback configuration (config/cyclonedds-loopback.xml) with DDS
     Security for "$1", made by scripts/make_test_ca.sh. -->
<CycloneDDS xmlns="https://cdds.io/config">
  <Domain Id="any">
    <General>
      <Interfaces><NetworkInterface address="127.0.0.1"/></Interfaces>
      <AllowMulticast>false</AllowMulticast>
    </General>
    <Discovery>
      <ParticipantIndex>auto</ParticipantIndex>
      <MaxAutoParticipantIndex>60</MaxAutoParticipantIndex>
      <Peers><Peer address="localhost"/></Peers>
    </Discovery>
    <Security>
      <Authentication>
        <Library path="$plugins/libdds_security_auth.so" initFunction="init_authentication" finalizeFunction="finalize_authentication"/>
        <IdentityCA>file:$out/$2.pem</IdentityCA>
        <IdentityCertificate>file:$out/$1.pem</IdentityCertificate>
        <PrivateKey>file:$out/$1_key.pem</PrivateKey>
      </Authentication>
      <AccessControl>
        <Library path="$plugins/libdds_security_ac.so" initFunction="init_access_control" finalizeFunction="finalize_access_control"/>
        <PermissionsCA>file:$out/$2.pem</PermissionsCA>
        <Governance>file:$out/governance_$2.xml.p7s</Governance>
        <Permissions>file:$out/permissions_$1.xml.p7s</Permissions>
      </AccessControl>
      <Cryptographic>
        <Library path="$plugins/libdds_security_crypto.so" initFunction="init_crypto" finalizeFunction="finalize_crypto"/>
      </Cryptographic>
    </Security>
  </Domain>
</CycloneDDS>
XML
}
governance() {  # CA: every protection on, every topic
  cat >"governance_$1.xml" <<XML
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>0</min><max>230</max></id_range></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>ENCRYPT</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
XML
  sign "governance_$1.xml" "$1"
}

make_ca ca "/C=NL/O=dem test/CN=dem test CA"
governance ca
for who in "${names[@]}"; do
  make_identity "$who" ca
  permissions "$who"
  sign "permissions_$who.xml" ca
  configuration "$who" ca
done
# Another CA and an identity of its own, signed documents and all: a
# participant that is authenticated - by the wrong authority.
make_ca other_ca "/C=NL/O=elsewhere/CN=another CA"
governance other_ca
make_identity intruder other_ca
permissions intruder
sign permissions_intruder.xml other_ca
configuration intruder other_ca
echo "$out"

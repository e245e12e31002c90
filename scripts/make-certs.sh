#!/usr/bin/env bash
# Makes what Fast DDS's DDS-Security plugins need for one swarm: a certificate authority, one
# certificate and key per participant name, a governance document and a permissions document,
# both signed by the CA (S/MIME), in OUT_DIR:
#
#   scripts/make-certs.sh OUT_DIR sim gcs leader-0 member-0-1 ... [--read-only swarm-view ...]
#
#   ca.pem ca.key                 the CA (its key stays here; nothing else needs it)
#   NAME.pem NAME.key             one identity per participant (subject CN=NAME, O=swarm)
#   governance.xml / .p7s         every topic: discovery, liveliness and data encrypted
#                                 (AES-GCM), joining only with a certificate of this CA
#   permissions.xml / .p7s        one grant per NAME: publish and subscribe on every topic and
#                                 partition of domains 0-232; anything else denied. A name after
#                                 --read-only may only subscribe: a watcher (`swarm view`)
#   grants.txt                    every name granted so far, with its mode: a later call adds
#                                 names (a viewer for a running deployment) and keeps the others'
#                                 grants; its certificates are signed by the same CA
#
# Each participant sends its own permissions document when it authenticates, so a viewer made
# after the swarm started (a newer permissions.p7s) is accepted by the running participants.
#
# A participant without a certificate of this CA cannot authenticate (PKI-DH), so it never
# matches the swarm's endpoints: it can neither read nor write its topics (tests: the rogue
# participant of tests/integration/test_security.cpp and deploy's rogue container).
# Keys are ECDSA P-256, as Fast DDS's PKI-DH expects. Certificates are valid for 10 years.
set -euo pipefail
usage() {
  echo "usage: scripts/make-certs.sh OUT_DIR NAME... [--read-only NAME...]" >&2
  exit 2
}
(($# >= 2)) || usage
out=$1
shift
names=()
declare -A mode_of=()
read_only=false
for arg in "$@"; do
  if [[ $arg == --read-only ]]; then
    read_only=true
    continue
  fi
  [[ $arg =~ ^[A-Za-z0-9._-]+$ ]] || { echo "make-certs.sh: bad participant name '$arg'" >&2; exit 2; }
  names+=("$arg")
  if $read_only; then mode_of[$arg]=read; else mode_of[$arg]=write; fi
done
((${#names[@]} > 0)) || usage
command -v openssl >/dev/null || { echo "make-certs.sh: openssl is missing (Debian package openssl)" >&2; exit 1; }
mkdir -p "$out"
cd "$out"

subject() { echo "/C=XX/O=swarm/CN=$1"; }
# The subject as Fast DDS compares it with a grant's subject_name (RFC 4514 order as openssl prints).
subject_name() { echo "CN=$1,O=swarm,C=XX"; }

if [[ ! -f ca.pem ]]; then
  openssl ecparam -name prime256v1 -genkey -noout -out ca.key
  openssl req -x509 -new -key ca.key -sha256 -days 3650 -subj "$(subject swarm-ca)" -out ca.pem
fi

for name in "${names[@]}"; do
  openssl ecparam -name prime256v1 -genkey -noout -out "$name.key"
  openssl req -new -key "$name.key" -subj "$(subject "$name")" -out "$name.csr"
  openssl x509 -req -in "$name.csr" -CA ca.pem -CAkey ca.key -CAcreateserial -days 3650 -sha256 \
    -out "$name.pem" 2>/dev/null
  rm -f "$name.csr"
done

cat >governance.xml <<'EOF'
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>0</min><max>232</max></id_range></domains>
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
EOF

# Every name granted so far, then this call's (a name given again takes its new mode).
if [[ -f grants.txt ]]; then
  while read -r name mode; do
    [[ -n ${mode_of[$name]:-} ]] || mode_of[$name]=$mode
  done <grants.txt
fi
printf '%s\n' "${!mode_of[@]}" | sort | while read -r name; do echo "$name ${mode_of[$name]}"; done >grants.txt

{
  cat <<'EOF'
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
EOF
  while read -r name mode; do
    # A read-only grant has no publish rule: its default, DENY, refuses every writer.
    publish='        <publish><topics><topic>*</topic></topics><partitions><partition>*</partition></partitions></publish>'
    [[ $mode == write ]] || publish='        <!-- read-only: no publish rule -->'
    cat <<EOF
    <grant name="$name">
      <subject_name>$(subject_name "$name")</subject_name>
      <validity><not_before>2020-01-01T00:00:00</not_before><not_after>2099-01-01T00:00:00</not_after></validity>
      <allow_rule>
        <domains><id_range><min>0</min><max>232</max></id_range></domains>
$publish
        <subscribe><topics><topic>*</topic></topics><partitions><partition>*</partition></partitions></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
EOF
  done <grants.txt
  cat <<'EOF'
  </permissions>
</dds>
EOF
} >permissions.xml

for doc in governance permissions; do
  openssl smime -sign -in "$doc.xml" -text -out "$doc.p7s" -signer ca.pem -inkey ca.key
done
echo "make-certs.sh: ${#names[@]} identities made in $out; $(wc -l <grants.txt) granted (grants.txt)"

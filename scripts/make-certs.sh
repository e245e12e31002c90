#!/usr/bin/env bash
# Makes what Fast DDS's DDS-Security plugins need for one swarm: a certificate authority, one
# certificate and key per participant name, a governance document and a permissions document,
# both signed by the CA (S/MIME), in OUT_DIR:
#
#   scripts/make-certs.sh OUT_DIR sim gcs leader-0 member-0-1 ...
#
#   ca.pem ca.key                 the CA (its key stays here; nothing else needs it)
#   NAME.pem NAME.key             one identity per participant (subject CN=NAME, O=swarm)
#   governance.xml / .p7s         every topic: discovery, liveliness and data encrypted
#                                 (AES-GCM), joining only with a certificate of this CA
#   permissions.xml / .p7s        one grant per NAME: publish and subscribe on every topic and
#                                 partition of domains 0-232; anything else denied
#
# A participant without a certificate of this CA cannot authenticate (PKI-DH), so it never
# matches the swarm's endpoints: it can neither read nor write its topics (tests: the rogue
# participant of tests/integration/test_security.cpp and deploy's rogue container).
# Keys are ECDSA P-256, as Fast DDS's PKI-DH expects. Certificates are valid for 10 years.
set -euo pipefail
if (($# < 2)); then
  echo "usage: scripts/make-certs.sh OUT_DIR NAME [NAME...]" >&2
  exit 2
fi
out=$1
shift
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

for name in "$@"; do
  [[ $name =~ ^[A-Za-z0-9._-]+$ ]] || { echo "make-certs.sh: bad participant name '$name'" >&2; exit 2; }
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

{
  cat <<'EOF'
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
EOF
  for name in "$@"; do
    cat <<EOF
    <grant name="$name">
      <subject_name>$(subject_name "$name")</subject_name>
      <validity><not_before>2020-01-01T00:00:00</not_before><not_after>2099-01-01T00:00:00</not_after></validity>
      <allow_rule>
        <domains><id_range><min>0</min><max>232</max></id_range></domains>
        <publish><topics><topic>*</topic></topics><partitions><partition>*</partition></partitions></publish>
        <subscribe><topics><topic>*</topic></topics><partitions><partition>*</partition></partitions></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
EOF
  done
  cat <<'EOF'
  </permissions>
</dds>
EOF
} >permissions.xml

for doc in governance permissions; do
  openssl smime -sign -in "$doc.xml" -text -out "$doc.p7s" -signer ca.pem -inkey ca.key
done
echo "make-certs.sh: CA, governance, permissions and $# identities in $out"

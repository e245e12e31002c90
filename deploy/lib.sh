# Shell helpers shared by the deploy/ scripts. Source it; it defines functions only.

# die CODE MESSAGE: one line on stderr naming the script, then exit CODE
# (1 runtime failure, 2 bad input or a missing prerequisite, as the role binaries do).
die() {
  local code=$1
  shift
  echo "$(basename "$0"): $*" >&2
  exit "$code"
}

say() { echo "$(basename "$0"): $*"; }

# Prints the Debian archive entries of this machine's apt configuration, one per line:
#   URI<TAB>SUITE<TAB>COMPONENTS
# from /etc/apt/sources.list, sources.list.d/*.list (one-line format) and sources.list.d/*.sources
# (deb822). Only binary ("deb") entries; deb822 stanzas with "Enabled: no" are skipped.
# APT_SOURCES_ROOT (default /etc/apt) lets a test point it at another folder.
apt_source_entries() {
  local root=${APT_SOURCES_ROOT:-/etc/apt}
  local f
  for f in "$root/sources.list" "$root"/sources.list.d/*.list; do
    [[ -f $f ]] || continue
    awk '
      { sub(/#.*/, "") }
      $1 != "deb" { next }
      {
        i = 2
        # Options: "[arch=amd64 signed-by=...]", possibly spread over several fields.
        if ($i ~ /^\[/) { while (i <= NF && $i !~ /\]$/) i++; i++ }
        if (i + 1 > NF) next
        uri = $i; suite = $(i + 1); comps = ""
        for (j = i + 2; j <= NF; j++) comps = comps (comps == "" ? "" : " ") $j
        printf "%s\t%s\t%s\n", uri, suite, comps
      }' "$f"
  done
  for f in "$root"/sources.list.d/*.sources; do
    [[ -f $f ]] || continue
    awk '
      function flush(   n, u, s, us, ss, a, b) {
        if (types ~ /(^| )deb( |$)/ && tolower(enabled) != "no") {
          n = split(uris, us, " "); m = split(suites, ss, " ")
          for (a = 1; a <= n; a++) for (b = 1; b <= m; b++) printf "%s\t%s\t%s\n", us[a], ss[b], comps
        }
        types = uris = suites = comps = enabled = ""
      }
      /^[ \t]*#/ { next }
      /^[ \t]*$/ { flush(); next }
      /^[ \t]/ { next }   # continuation lines only occur in Signed-By blocks
      {
        key = tolower($1); sub(/:$/, "", key)
        val = $0; sub(/^[^:]*:[ \t]*/, "", val); gsub(/[ \t]+/, " ", val)
        if (key == "types") types = val
        else if (key == "uris") uris = val
        else if (key == "suites") suites = val
        else if (key == "components") comps = val
        else if (key == "enabled") enabled = val
      }
      END { flush() }' "$f"
  done
}

# The Debian mirror URI serving SUITE (e.g. bookworm), from this machine's apt configuration.
# Empty when none is configured.
debian_mirror_for() {
  apt_source_entries | awk -F'\t' -v s="$1" '$2 == s { print $1; exit }'
}

# The compose command to use: "docker compose" (v2 plugin) when it works, else "docker-compose"
# (v1). Prints nothing when neither is installed.
compose_command() {
  if docker compose version >/dev/null 2>&1; then
    echo "docker compose"
  elif command -v docker-compose >/dev/null 2>&1; then
    echo "docker-compose"
  fi
}

# Every installed compose command, one per line ("docker compose", "docker-compose").
compose_commands() {
  docker compose version >/dev/null 2>&1 && echo "docker compose"
  command -v docker-compose >/dev/null 2>&1 && echo "docker-compose"
  return 0
}

# True when a Docker engine answers.
docker_engine_running() {
  command -v docker >/dev/null 2>&1 && docker info >/dev/null 2>&1
}

# scenario_size FILE: prints "GROUPS ROBOTS_PER_GROUP" from a scenario file's top-level groups: and
# robots_per_group: lines (no indentation); an absent field is the proto default, 3.
scenario_size() {
  local g r
  g=$(sed -n 's/^groups:[[:space:]]*\([0-9][0-9]*\).*/\1/p' "$1" | tail -n 1)
  r=$(sed -n 's/^robots_per_group:[[:space:]]*\([0-9][0-9]*\).*/\1/p' "$1" | tail -n 1)
  echo "${g:-3} ${r:-3}"
}

# stall_timeout CONTAINERS: the seconds a role waits for discovery or a peer before it gives up
# (SWARM_STALL_TIMEOUT's default in the generated files). The engine starts the containers one
# after another (compose: ~1.4 s each measured here, 53 containers: 76 s), and the first ones must
# outwait the last: 3 s per container, at least 60 s.
stall_timeout() { echo $(($1 * 3 > 60 ? $1 * 3 : 60)); }

# role_security_files NAME: the files a role named NAME reads for DDS-Security, one per line: the
# CA certificate, the signed governance and permissions, its own certificate and key
# (scripts/make-certs.sh makes them; comm's use_security reads them by these names).
role_security_files() { printf '%s\n' ca.pem governance.p7s permissions.p7s "$1.pem" "$1.key"; }

# Shell helpers for the deploy tests' checks of a run's metrics.json, which nlohmann::json
# pretty-prints with 2 spaces per level and its keys sorted. Source it after setting
# `test_name` (the prefix of messages) and `metrics` (the file).
#
#   test_name=cut_leader metrics=$out/metrics.json
#   source "$src/tests/deploy/metrics_checks.sh"
#   lost=$(faults_list agents_lost)

# Fails the test with a message and the faults section.
fail() {
  echo "$test_name: $*" >&2
  sed -n '/"faults"/,/^  }/p' "$metrics" >&2
  exit 1
}

# The list `faults.KEY`, on one line without spaces (none of its entries holds a list).
faults_list() {
  local faults
  faults=$(sed -n '/^  "faults": {/,/^  }/p' "$metrics" | tr -d ' \n')
  [[ $faults =~ \"$1\":\[([^]]*)\] ]] || fail "metrics.json has no faults.$1"
  echo "${BASH_REMATCH[1]}"
}

# The object that holds LINE (a sed pattern), as one line without spaces.
block_of() { sed -n "/$1/,/}/p" "$metrics" | tr -d ' \n'; }

# Shell helpers that read a finished run's metrics.json, shared by compose-test.sh and
# stack-test.sh. Source it; it defines functions only. metrics.json is written by nlohmann::json
# dump(2): top-level keys sit at two spaces, sorted.

# top_value KEY FILE: a top-level scalar's value.
top_value() { sed -n "s/^  \"$1\": \(.*\)$/\1/p" "$2" | sed 's/,$//'; }

# summary FILE: steps, mission seconds and ticks per second, for a test's last line.
summary() {
  echo "$(top_value steps "$1") steps, $(top_value wall_seconds "$1") s of mission," \
    "$(top_value ticks_per_second "$1" | awk '{ printf "%.1f", $1 }') ticks/s"
}

# as_set LIST: a JSON list of names ("[\"a\",\"b\"]") as its sorted, comma-separated items.
as_set() { tr -d '[]' <<<"$1" | tr , '\n' | sed '/^$/d' | sort | paste -sd, -; }

# check_results DIR EXPECTED_MISSING: DIR holds metrics.json (complete: true) and run.pb, and the
# agents whose report never reached the GCS are exactly EXPECTED_MISSING (a JSON list of names,
# "[]" for none). Names every difference on stderr; returns 1 when there is one.
check_results() {
  local dir=$1 want=$2 ok=0 missing
  [[ -s $dir/metrics.json ]] || { echo "$(basename "$0"): the GCS wrote no metrics.json to the results volume" >&2; return 1; }
  [[ -s $dir/run.pb ]] || { echo "$(basename "$0"): the GCS wrote no run.pb to the results volume" >&2; ok=1; }
  if [[ $(top_value complete "$dir/metrics.json") != true ]]; then
    echo "$(basename "$0"): metrics.json says complete: $(top_value complete "$dir/metrics.json") (expected true)" >&2
    ok=1
  fi
  # An empty array is written on one line ("reports_missing": []), a full one over several.
  missing=$(top_value reports_missing "$dir/metrics.json")
  if [[ $missing != "[]" ]]; then
    missing=$(sed -n '/^  "reports_missing": \[/,/^  \]/p' "$dir/metrics.json" | tr -d ' \n' |
              sed 's/^"reports_missing"://; s/,$//')
  fi
  # As sets: metrics.json lists them in agent-id order.
  if [[ $(as_set "$missing") != "$(as_set "$want")" ]]; then
    echo "$(basename "$0"): agents whose report never reached the GCS (reports_missing): $missing" \
      "(expected $want)" >&2
    ok=1
  fi
  return "$ok"
}

#!/usr/bin/env bash
# The whole suite at the library's defaults, beside each task's best documented setting, in a few
# minutes (docs/experiments.md, "Learning at defaults"): the thesis's tasks, the changing worlds and
# the corridor (verve-experiments --defaults: only the task's sensors, actions and features),
# Gymnasium's classic control (verve-classic) and the Bullet scenes (verve-demo run --defaults).
# A rule becomes a default only when this table says it helps overall: run it before and after,
# and put both in the commit message.
#   ./scripts/defaults_table.sh            # about 4 minutes on 2 cores
#   SEEDS=4 ./scripts/defaults_table.sh    # classic control on fewer seeds: quicker, noisier
#   DEFAULTS_ONLY=1 CANDIDATE="policy_weight_bound=10" ./scripts/defaults_table.sh
#                                          # a candidate default in the defaults column, nothing else
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh verve-experiments verve-classic verve-demo >/dev/null
experiments=build/samples/tasks/verve-experiments
classic=build/samples/tasks/verve-classic
demo=build/samples/runner/verve-demo
seeds=${SEEDS:-10}
# CANDIDATE="key=value ..." adds settings to the defaults column: a candidate default, measured
# before it is made one.
candidate=()
for s in ${CANDIDATE:-}; do candidate+=(--set "$s"); done

# Mean of a curve column over trials [first, last) of a verve-experiments CSV (trial numbers from 0).
window_mean() {  # csv column first last
  awk -F, -v col="$2" -v a="$3" -v b="$4" '
    NR == 1 { for (i = 1; i <= NF; i++) if ($i == col) c = i; next }
    $1 >= a && $1 < b { s += $c; n++ }
    END { if (n) printf "%.3f", s / n; else printf "n/a" }' "$1"
}

printf '%-38s %-9s %12s %12s   %s\n' task metric defaults "thesis/best" "anchor (what the task's own settings aim at)"
# task  runs  trials  metric-column  window-first  window-last  anchor
while read -r task runs trials column first last anchor; do
  [ -z "$task" ] || [ "${task:0:1}" = "#" ] && continue
  tmp=$(mktemp)
  "$experiments" run "$task" --runs "$runs" --trials "$trials" --defaults "${candidate[@]}" --csv "$tmp" >/dev/null
  d=$(window_mean "$tmp" "$column" "$first" "$last")
  t=skipped
  if [ -z "${DEFAULTS_ONLY:-}" ]; then
    "$experiments" run "$task" --runs "$runs" --trials "$trials" --csv "$tmp" >/dev/null
    t=$(window_mean "$tmp" "$column" "$first" "$last")
  fi
  rm -f "$tmp"
  printf '%-38s %-9s %12s %12s   %s\n' "$task" "$column" "$d" "$t" "${anchor//_/ }"
done <<'TASKS'
bandit                            200  1000  reward   900  1000  best_lever_~1.55
sequential-actions                 40   700  success  630   700  100%_correct_late_in_each_block
hot-plate-1d                      100    31  steps     28    31  optimal_~4.5
hot-plate-1d-continuous           100    31  steps     28    31  optimal_~4.5
signaled-hot-plate-1d             100    81  steps     73    81  uses_the_signal
signaled-hot-plate-1d-continuous  100    81  steps     73    81  uses_the_signal
hot-plate-2d                       50   301  steps    271   301  optimal_~2.8
hot-plate-2d-continuous            50   301  steps    271   301  optimal_~2.8
signaled-hot-plate-2d              30  1601  steps   1441  1601  optimal_~9.5
signaled-hot-plate-2d-continuous   30  1601  steps   1441  1601  optimal_~9.5
signaled-hot-plate-1d-2-distractors   20   301  steps    271   301  optimal_~9.5_(4_sensors:_one_lattice,_pairs_beside)
signaled-hot-plate-1d-6-distractors   20   301  steps    271   301  optimal_~9.5_(8_sensors:_groups)
signaled-hot-plate-1d-14-distractors  20   301  steps    271   301  optimal_~9.5_(16_sensors:_groups)
signaled-hot-plate-1d-30-distractors  20   301  steps    271   301  optimal_~9.5_(32_sensors:_groups)
signaled-hot-plate-2d-branches        20   301  steps    271   301  optimal_~4.9_(3x3x2_action_branches)
signaled-hot-plate-2d-18-moves        20   301  steps    271   301  optimal_~4.9_(the_same_18_moves_as_one_set)
steering-car                       20   301  steps    271   301  scripted_driver_73_(steering,_throttle:_2_continuous_actions)
steering-car-branches              20   301  steps    271   301  scripted_driver_73_(the_same_car_by_3x3_branches)
maze1                              20   100  steps     90   100  optimal_22
maze1-continuous                   20   100  steps     90   100  optimal_22
maze2                              10    51  steps     46    51  optimal_25
maze2-continuous                   40    51  steps     46    51  optimal_25_(1_in_10-20_runs_can_stall:_40_runs)
maze2-planning                     10    51  steps     46    51  optimal_25,_faster_than_maze2
curiosity-grid-curious             10    81  reward    73    81  more_than_plain_RL
corridor                           10   100  steps     90   100  optimal_39
cue-change                         20  2000  success 1200  1250  >=_0.9_within_250_trials_of_the_change
maze1-moving-goal                  20   150  steps    140   150  optimal_after_the_move
swapping-hot-plate-1d              50   300  steps    270   300  re-learns_the_other_end
TASKS

echo
printf '%-22s %-34s %-34s %s\n' task "defaults: solved" "best setting: solved" "RL Zoo's tuned agent"
while read -r task best; do
  summary() { "$classic" "$task" --seeds "$seeds" "$@" | awk '/^# solved/ { sub(/;/, "", $5); printf "%s/%s, median %s", $3, $5, $8 }'; }
  d=$(summary "${candidate[@]}")
  b=skipped
  [ -n "${DEFAULTS_ONLY:-}" ] || b=$(summary $(for s in $best; do printf -- '--set %s ' "$s"; done))
  zoo=$("$classic" "$task" --seeds 1 --budget 1 | awk -F'RL Zoo ' 'NR == 1 { print $2 }')
  printf '%-22s %-34s %-34s %s\n' "$task" "$d" "$b ($best)" "$zoo"
done <<'TASKS'
cart-pole-v1     tau_discount=10 tau_value=0.01
acrobot-v1       tau_discount=10 tau_value=0.01
mountain-car-v0  tau_discount=10 tau_value=0.01
pendulum-v1      resolution=16 tau_value=0.01
pendulum-v1-continuous resolution=16
TASKS

# The Bullet scenes (verve-demo run SCENE --defaults), beside the scene's own settings (the thesis's
# for the pendulum and the cart-pole, the arena's tuned horizon and traces).
echo
printf '%-16s %-44s %12s %12s   %s\n' scene metric defaults "scene's own" anchor
scene_out=$(mktemp -d)
trap 'rm -rf "$scene_out"' EXIT
scene() {  # scene metric-kind [verve-demo flags...]
  local name=$1 kind=$2
  shift 2
  case $kind in
    last10)  # the mean reward per step of the last 10 trials, over 10 runs
      "$demo" run "$name" --runs 10 --out "$scene_out" --no-save "$@" | awk '/^Learned/ { print $NF }' ;;
    solved)  # the cart-pole's trials until one lasts the full 1800 s, over 4 runs (unsolved: the trial count + 1)
      "$demo" run "$name" --runs 4 --out "$scene_out" --no-save "$@" | awk '
        /reached the full trial/ { s += $NF; n++; r++ } /not solved in/ { s += $6 + 1; n++ }
        END { printf "%d/%d, %.0f", r, n, s / n }' ;;
    food)  # food per NPC-minute over minutes 16-20, seeds 1-3, 8 NPCs
      for seed in 1 2 3; do
        "$demo" run "$name" --trials 20 --seed "$seed" --out "$scene_out" --no-save "$@" >/dev/null
        awk -F, 'NR > 1 && $1 > 15 { s += $2; n++ } END { print s / n }' "$scene_out/$name-curve.csv"
      done | awk '{ s += $1 } END { printf "%.2f", s / NR }' ;;
  esac
}
while read -r name kind metric anchor; do
  [ -z "$name" ] && continue
  d=$(scene "$name" "$kind" --defaults "${candidate[@]}")
  t=skipped
  [ -n "${DEFAULTS_ONLY:-}" ] || t=$(scene "$name" "$kind")
  printf '%-16s %-44s %12s %12s   %s\n' "$name" "${metric//_/ }" "$d" "$t" "${anchor//_/ }"
done <<'SCENES'
pendulum   last10  reward_per_step,_last_10_trials              swings_up_and_holds:_~0.8
cart-pole  solved  runs_reaching_1800_s,_mean_trial             thesis:_a_few_hundred_trials
npc-arena  food    food_per_NPC-minute,_minutes_16-20           more_than_early
SCENES

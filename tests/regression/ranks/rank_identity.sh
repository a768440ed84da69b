#!/usr/bin/env bash
# A run over N MPI ranks gives the files of the run on one rank, byte for byte (docs/parallel.md:
# every sum in the same order whatever the rank count). Not a comparison with an earlier output:
# the property itself, on the model kinds whose passes differ (shells with J2, nodal and pressure
# loads, a rigid punch's contact, the three-layer cup's cohesive interfaces, the hot draw's heat
# and contacts, a solid block, a rigid wall and a tied contact, the DCB's cohesive strip), also
# while the ranks split the model again as they run (--rebalance); an instability and a
# non-finite velocity on 3 ranks (the diagnosis, the exit code and the files of the run on one);
# and a run stopped on 2 ranks and restarted on 2 and on 1 (the files those of the uninterrupted
# run on one rank).
#
#   rank_identity.sh PLYFORM WORKDIR
set -euo pipefail
plyform=$1
work=$2
src=$(cd "$(dirname "$0")/../../.." && pwd)
# CI runs as root; the ranks share this machine's cores (more ranks than cores: OpenMPI yields).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# Containers often forbid the cross-memory attach of OpenMPI's shared-memory transport: copy
# through the shared segment instead.
export OMPI_MCA_btl_vader_single_copy_mechanism=none
rm -rf "$work"
mkdir -p "$work"
cd "$work"

# A machine whose MPI cannot start two processes at all cannot run this test (ctest: skipped,
# exit 77), and says why; a plyform that starts there and fails is a failure.
if ! mpirun -np 2 "$plyform" --version > mpi_probe.log 2>&1; then
  echo "SKIP: mpirun cannot start 2 processes on this machine:"
  cat mpi_probe.log
  exit 77
fi

python3 "$src/bench/decks/plate.py" plate --n 24 --cycles 300
python3 "$src/bench/decks/plate.py" punch --n 24 --punch --cycles 700
# The plate with nodal loads and a follower pressure on two elements: the loaded nodes, which
# every rank moves where each rank moves its own nodes, and the loads' power summed over them.
mkdir -p loads
sed '$d' plate/plate.k > loads/plate.k
cat >> loads/plate.k << 'EOF'
*DEFINE_CURVE
        77
                 0.0                 1.0
                 1.0                 1.0
*LOAD_NODE_POINT
       100         3        77     -20.0
       333         1        77      15.0
*LOAD_SEGMENT
        77     -0.05       0.0       201       202       227       226
        77     -0.05       0.0       400       401       426       425
*END
EOF
python3 "$src/examples/square_cup/generate.py" cup --layers 3 --n 8 --plain --depth 3 > /dev/null
python3 "$src/examples/deep_drawing/generate.py" draw --n 6 --end 0.001 > /dev/null
python3 "$src/examples/solid_block/generate.py" block --elements 6 > /dev/null
mkdir -p wall  # a moving rigid wall striking a bar of two tied halves
cp "$src/tests/regression/run/decks/restart_wall_tied.k" wall/
python3 "$src/examples/dcb/generate.py" dcb --dx 1.0 --end 0.001 > /dev/null

failed=0
same_files() {  # same_files A B: every file of A in B, byte for byte (summary.json aside)
  local a=$1 b=$2 f
  while IFS= read -r f; do
    if ! cmp -s "$a/$f" "$b/$f"; then
      echo "FAIL: $b/$f differs from $a/$f"
      failed=1
    fi
  done < <(cd "$a" && find . -type f ! -name summary.json ! -name d3dump | sort)
}

run_on() {  # run_on RANKS DECK OUT [ARGS...]
  local np=$1 deck=$2 out=$3
  shift 3
  if [[ $np == 1 ]]; then
    "$plyform" run "$deck" -o "$out" "$@" > "$out.log" 2>&1 || { cat "$out.log"; return 1; }
  else
    mpirun -np "$np" "$plyform" run "$deck" -o "$out" "$@" > "$out.log" 2>&1 ||
      { cat "$out.log"; return 1; }
    grep -q "\"ranks\": $np" "$out/summary.json" || { echo "FAIL: $out/summary.json: ranks"; failed=1; }
  fi
}

for model in plate/plate.k loads/plate.k punch/plate.k cup/square_cup_3.k draw/deep_drawing.k \
  block/solid_block.k wall/restart_wall_tied.k dcb/dcb.k; do
  name=$(dirname "$model")
  run_on 1 "$model" "$name.1"
  for np in 2 3 4; do
    run_on "$np" "$model" "$name.$np"
    same_files "$name.1" "$name.$np"
  done
  # Split again every 50 cycles or so (the shares from the ranks' measured seconds, which on
  # oversubscribed cores change from look to look): who computes what moves, the files do not.
  run_on 3 "$model" "$name.3r" --rebalance 50
  same_files "$name.1" "$name.3r"
  splits=$(grep -o '"splits": [0-9]*' "$name.3r/summary.json" | grep -o '[0-9]*$')
  [[ ${splits:-0} -ge 1 ]] || { echo "FAIL: $name.3r was not split again"; failed=1; }
  echo "$name: 1, 2, 3 and 4 ranks compared, and 3 ranks split again $splits times"
done

# Where no pass reads every node each rank moves its own (summary.json's moved_nodes, one count
# per rank, each below the model's nodes); under contact every rank moves every node (empty).
moved=$(grep -o '"moved_nodes": \[[0-9, ]*\]' plate.2/summary.json | grep -o '\[.*\]')
nodes=$(grep -o '"nodes": [0-9]*' plate.2/summary.json | head -n 1 | grep -o '[0-9]*$')
python3 -c "import sys; m = $moved; sys.exit(0 if len(m) == 2 and all(0 < x < $nodes for x in m) else 1)" ||
  { echo "FAIL: plate.2 moved_nodes $moved of $nodes"; failed=1; }
grep -q '"moved_nodes": \[\]' punch.2/summary.json ||
  { echo "FAIL: punch.2 moved_nodes not empty"; failed=1; }
echo "moved nodes on 2 ranks: the plate $moved of $nodes, the punched plate every node"

# stops_as_on_one NAME DECK WHAT EXPECTED: the run fails on 1 and on 3 ranks with the same
# diagnosis (containing EXPECTED), exit code 3 and the same files, and no rank waits for the others.
stops_as_on_one() {
  local name=$1 deck=$2 what=$3 expected=$4 np code
  for np in 1 3; do
    code=0
    if [[ $np == 1 ]]; then
      "$plyform" run "$deck" -o "$name.$np" > "$name.$np.out" 2> "$name.$np.err" || code=$?
    else
      mpirun -np $np "$plyform" run "$deck" -o "$name.$np" > "$name.$np.out" 2> "$name.$np.err" ||
        code=$?
    fi
    [[ $code != 0 ]] || { echo "FAIL: $what ran to its end on $np rank(s)"; failed=1; }
  done
  grep "^error" "$name.1.err" > "$name.1.diagnosis" || true
  grep "^error" "$name.3.err" > "$name.3.diagnosis" || true
  if ! grep -q "$expected" "$name.1.diagnosis" || ! cmp -s "$name.1.diagnosis" "$name.3.diagnosis"
  then
    echo "FAIL: $what: the diagnosis on 3 ranks is not the one on 1:"
    cat "$name.1.diagnosis" "$name.3.diagnosis"
    failed=1
  fi
  grep -q "Exit code: *3" "$name.3.err" || { echo "FAIL: $what: the ranks did not exit 3"; failed=1; }
  same_files "$name.1" "$name.3"
  echo "$what on 1 and 3 ranks compared: $(cut -c1-80 "$name.1.diagnosis")"
}

# An instability (the solid block's top face driven 100 times too far: its energy leaves the
# band).
mkdir -p unstable
sed '/^\$     LCID      SIDR       SFA       SFO/{n;s/.*/         1         0       1.0     100.0/}' \
  block/solid_block.k > unstable/solid_block.k
stops_as_on_one unstable unstable/solid_block.k "an instability" "left the band"

# A non-finite velocity (a load of 2e308 thrown onto one node of the plain plate, where each rank
# moves its own nodes): the ranks agree on the node.
mkdir -p nan
sed '$d' plate/plate.k > nan/plate.k
cat >> nan/plate.k << 'EOF'
*DEFINE_CURVE
        78
                 0.0                 0.0
              0.0005                 0.0
             0.00051             1.0e308
                 1.0             1.0e308
*LOAD_NODE_POINT
       300         3        78       2.0
*END
EOF
stops_as_on_one nan nan/plate.k "a non-finite velocity" "non-finite velocity"

# Restart on 2 ranks: a run stopped by SIGTERM sent to one of its ranks (every rank stops at the
# same cycle and the first writes the checkpoint), then continued on 2 ranks, and on 1: the files
# of the run on one rank without a stop (docs/restart.md: wherever the stop fell). Under the
# punch (every rank moves every node: the contact's search reads them all) and without it (each
# rank moves its own nodes and the ranks agree on the stop in the velocity pass).
# The second splits the model again at every look (every 50 cycles), so that the signal may land
# inside METIS, which catches SIGTERM during its calls where a handler would see it (the process
# takes the stop signals on a thread of its own: app/stop_signals.hpp).
restart_on_2() {  # restart_on_2 NAME "RUN ARGS" [plate.py ARGS...]
  local name=$1 run_args=$2 launcher rank status
  shift 2
  python3 "$src/bench/decks/plate.py" "$name" --n 24 "$@"
  run_on 1 "$name/plate.k" "$name.r1"
  # shellcheck disable=SC2086
  mpirun -np 2 "$plyform" run "$name/plate.k" -o "$name.r2" $run_args > "$name.r2.log" 2>&1 &
  launcher=$!
  for _ in $(seq 100); do  # until its first rows are out (at most 10 s)
    [[ -f $name.r2/glstat.csv && $(wc -l < "$name.r2/glstat.csv") -ge 4 ]] && break
    sleep 0.1
  done
  rank=$(pgrep -P "$launcher" plyform | head -n 1)
  kill -TERM "$rank"
  status=0
  wait "$launcher" || status=$?
  if ! grep -q "stopped by a signal" "$name.r2.log"; then
    echo "FAIL: the run on 2 ranks did not stop on the signal (exit $status):"
    cat "$name.r2.log"
    exit 1
  fi
  cp -r "$name.r2" "$name.r2to1"  # the checkpoint holds the whole state: any rank count goes on
  run_on 2 "$name/plate.k" "$name.r2" --restart
  same_files "$name.r1" "$name.r2"
  run_on 1 "$name/plate.k" "$name.r2to1" --restart
  same_files "$name.r1" "$name.r2to1"
  echo "$name: restart on 2 ranks compared ($(grep -o "\"restarted_at\": [0-9.e+-]*" \
    "$name.r2/summary.json"))"
}
restart_on_2 long "" --punch --cycles 8000
restart_on_2 long_plain "--rebalance 1" --cycles 16000
exit $failed

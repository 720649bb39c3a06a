#!/usr/bin/env bash
# The Python module against the command on the same mesh: umbra.render of
# the 1.2M-triangle bunny handed over as NumPy arrays (read beforehand from
# the file by umbra.load, as a pipeline holds a mesh), and umbra render on
# the file, both at the default 800x800, one fresh process each, rounds
# alternating. The module's figure is the call alone (GL context
# included); its process's wall time, Python and NumPy starting included,
# is beside it.
#
#   bench/python_arrays.sh [RUNS]    (default 5; after ./build.sh test)
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/timing.sh
runs=${1:-5}
build=build
data=$build/bench-data
require_engine_and_bunny $build
export PYTHONPATH=$PWD/$build/python
/usr/bin/python3 -c "
import numpy as np, umbra
mesh = umbra.load('$data/bunny-1M.glb')
np.save('$data/bunny-1M-vertices.npy', mesh.vertices)
np.save('$data/bunny-1M-faces.npy', mesh.faces)
print(f'{len(mesh.faces)} triangles, {len(mesh.vertices)} vertices')"
rm -f "$data/python-call.txt"
rows=("umbra render bunny-1M.glb (the command, on the file)|$build/umbra render $data/bunny-1M.glb -o $data/python-cmp.png --size 800x800"
      "python3: umbra.render((vertices, faces)) (whole process)|/usr/bin/python3 bench/python_render.py $data/bunny-1M-vertices.npy $data/bunny-1M-faces.npy $data/python-call.txt")
time_rows "$data/python" "$runs"
echo "$(nproc) cores; $runs rounds"
echo
echo "| program | median wall time (s) | median peak memory (MiB) |"
echo "|---|---|---|"
rows_table "$data/python"
command=$(median_of "$data/python-0.txt" 1)
call=$(median < "$data/python-call.txt")
echo
echo "umbra.render((vertices, faces)) alone: median $call s, $(echo "$call / $command" | bc -l | cut -c1-4)x the command's $command s"

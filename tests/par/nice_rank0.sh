#!/bin/sh
# Runs its arguments, rank 0 of an Open MPI job at the lowest priority (nice 19): with
# more ranks than cores, rank 0 then gets little CPU, and its neighbours' cavities may
# take all its tets (tests/par/CMakeLists.txt, par_mpi_mesh_cube_starved_rank_np3).
if [ "${OMPI_COMM_WORLD_RANK:-}" = 0 ]; then exec nice -n 19 "$@"; fi
exec "$@"

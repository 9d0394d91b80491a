// liggghts_tri: the Debian LIGGGHTS 3.8.0 binary with the upstream triclinic fix applied at run
// time. LIGGGHTS 3.8.0's Domain constructor sets prd_lamda = prd_half_lamda = 0 (upstream fixed it
// in CFDEMproject/LIGGGHTS-PUBLIC commits 1945ea49 and 84e3a84c, Jan/Feb 2020, after the 3.8.0
// release that Debian packages): with a triclinic box no ghost atoms are made, so grains never
// touch across a periodic boundary. Here the two arrays are set to their correct values
// (lamda box = 1, half = 0.5) right after the instance is built and before the input is read.
// Usage: liggghts_tri -in FILE [-nocite ...]   (same arguments as liggghts)
#include <mpi.h>

#include "domain.h"
#include "input.h"
#include "lammps.h"
using namespace LAMMPS_NS;
int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  LAMMPS* lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  for (int i = 0; i < 3; ++i) {
    lmp->domain->prd_lamda[i] = 1.0;
    lmp->domain->prd_half_lamda[i] = 0.5;
  }
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}

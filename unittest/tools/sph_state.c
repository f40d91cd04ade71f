/* sph_state: run a LAMMPS input through the C library interface and write
   the SPH state of every atom, sorted by id, for regression tests:
     id type x y z T desph rho drho vx vy vz fx fy fz
   usage: [mpirun -np N] sph_state <out-file> <input> [LAMMPS args, e.g. -var k v]
   Built twice: against the host LAMMPS (inputs load the plugin) and against
   the LAMMPS with USER-SPHTHERMAL compiled in. */

#define LAMMPS_LIB_MPI
#include "library.h"

#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

static double *gather(void *lmp, const char *name, int count, int natoms)
{
  double *data = (double *) malloc(sizeof(double) * (size_t) count * (size_t) natoms);
  lammps_gather_atoms(lmp, (char *) name, 1, count, data);
  return data;
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  if (argc < 3) {
    fprintf(stderr, "usage: %s <out-file> <input> [LAMMPS args]\n", argv[0]);
    MPI_Finalize();
    return 2;
  }
  int me;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);

  /* LAMMPS sees: sph_state -log none -screen none <extra args> */
  int lmp_argc = argc - 3 + 5;
  char **lmp_argv = (char **) malloc(sizeof(char *) * (size_t) (lmp_argc + 1));
  lmp_argv[0] = argv[0];
  lmp_argv[1] = (char *) "-log";
  lmp_argv[2] = (char *) "none";
  lmp_argv[3] = (char *) "-screen";
  lmp_argv[4] = (char *) "none";
  for (int i = 3; i < argc; i++) lmp_argv[i + 2] = argv[i];
  lmp_argv[lmp_argc] = NULL;

  void *lmp = lammps_open(lmp_argc, lmp_argv, MPI_COMM_WORLD, NULL);
  if (!lmp) {
    fprintf(stderr, "sph_state: could not create LAMMPS\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  lammps_file(lmp, argv[2]);
  if (lammps_has_error(lmp)) {
    char message[2048];
    lammps_get_last_error_message(lmp, message, sizeof(message));
    if (me == 0) fprintf(stderr, "sph_state: %s\n", message);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }

  const int natoms = (int) lammps_get_natoms(lmp);
  int *type = (int *) malloc(sizeof(int) * (size_t) natoms);
  lammps_gather_atoms(lmp, (char *) "type", 0, 1, type);
  double *x = gather(lmp, "x", 3, natoms);
  double *esph = gather(lmp, "esph", 1, natoms);
  double *cv = gather(lmp, "cv", 1, natoms);
  double *desph = gather(lmp, "desph", 1, natoms);
  double *rho = gather(lmp, "rho", 1, natoms);
  double *drho = gather(lmp, "drho", 1, natoms);
  double *v = gather(lmp, "v", 3, natoms);
  double *f = gather(lmp, "f", 3, natoms);

  if (me == 0) {
    FILE *out = fopen(argv[1], "w");
    if (!out) {
      fprintf(stderr, "sph_state: cannot write %s\n", argv[1]);
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    fprintf(out, "# id type x y z T desph rho drho vx vy vz fx fy fz\n");
    for (int i = 0; i < natoms; i++)
      fprintf(out,
              "%d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
              i + 1, type[i], x[3 * i], x[3 * i + 1], x[3 * i + 2], esph[i] / cv[i], desph[i], rho[i],
              drho[i], v[3 * i], v[3 * i + 1], v[3 * i + 2], f[3 * i], f[3 * i + 1], f[3 * i + 2]);
    fclose(out);
  }

  lammps_close(lmp);
  MPI_Finalize();
  return 0;
}

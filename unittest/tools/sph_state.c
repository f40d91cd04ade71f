/* sph_state: run a LAMMPS input through the C library interface and write
   the SPH state of every atom, sorted by id, for regression tests:
     id type x y z T desph rho drho vx vy vz fx fy fz
   usage: [mpirun -np N] sph_state <out-file> <input> [LAMMPS args, e.g. -var k v]
   Built twice: against the host LAMMPS (inputs load the plugin) and against
   the LAMMPS with USER-SPHTHERMAL compiled in. */

#define LAMMPS_LIB_MPI
#include "library.h"

#include <mpi.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* The owned atoms' IDs and values, gathered on rank 0 by the driver itself:
   LAMMPS's lammps_gather_atoms() refuses -DLAMMPS_BIGBIG (its error would
   only be seen by lammps_has_error), so each rank sends its atoms with their
   IDs and rank 0 puts every value in the row of its ID. */
typedef struct {
  int nlocal, nranks, me, natoms;
  int *counts, *displs;    /* per rank, in atoms (rank 0) */
  long long *ids;          /* every atom's ID in the order received (rank 0) */
} Gathered;

static void gather_ids(void *lmp, Gathered *g)
{
  g->natoms = (int) lammps_get_natoms(lmp);
  MPI_Comm_rank(MPI_COMM_WORLD, &g->me);
  MPI_Comm_size(MPI_COMM_WORLD, &g->nranks);
  g->nlocal = lammps_extract_setting(lmp, "nlocal");
  const int tag_bytes = lammps_extract_setting(lmp, "tagint");
  const void *tag = lammps_extract_atom(lmp, "id");
  long long *mine = (long long *) malloc(sizeof(long long) * (size_t) (g->nlocal + 1));
  for (int i = 0; i < g->nlocal; i++)
    mine[i] = (tag_bytes == 8) ? (long long) ((const int64_t *) tag)[i]
                               : (long long) ((const int *) tag)[i];
  g->counts = (int *) malloc(sizeof(int) * (size_t) g->nranks);
  g->displs = (int *) malloc(sizeof(int) * (size_t) g->nranks);
  MPI_Gather(&g->nlocal, 1, MPI_INT, g->counts, 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  if (g->me == 0)
    for (int r = 0; r < g->nranks; r++) {
      g->displs[r] = total;
      total += g->counts[r];
    }
  g->ids = (long long *) malloc(sizeof(long long) * (size_t) (total + 1));
  MPI_Gatherv(mine, g->nlocal, MPI_LONG_LONG, g->ids, g->counts, g->displs, MPI_LONG_LONG, 0,
              MPI_COMM_WORLD);
  free(mine);
  if (g->me == 0) {
    if (total != g->natoms) {
      fprintf(stderr, "sph_state: %d owned atoms, LAMMPS counts %d\n", total, g->natoms);
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    /* every row is written once: an ID out of range or given twice would
       leave a row of uninitialised values */
    char *seen = (char *) calloc((size_t) total + 1, 1);
    for (int n = 0; n < total; n++) {
      if (g->ids[n] < 1 || g->ids[n] > total) {
        fprintf(stderr, "sph_state: atom ID %lld is not in 1..%d (the IDs must be consecutive)\n",
                g->ids[n], total);
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
      if (seen[g->ids[n]]++) {
        fprintf(stderr, "sph_state: atom ID %lld is given to more than one atom\n", g->ids[n]);
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
    }
    free(seen);
  }
}

/* count values per atom of the per-atom property 'name' (a double vector, a
   double array, or with count 1 and is_int an int vector), by atom ID */
static double *gather(void *lmp, const Gathered *g, const char *name, int count, int is_int)
{
  const void *data = lammps_extract_atom(lmp, name);
  if (!data && g->nlocal > 0) {
    fprintf(stderr, "sph_state: LAMMPS has no per-atom '%s'\n", name);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  double *mine = (double *) malloc(sizeof(double) * (size_t) (count * g->nlocal + 1));
  for (int i = 0; i < g->nlocal; i++)
    for (int k = 0; k < count; k++)
      mine[count * i + k] = is_int  ? (double) ((const int *) data)[i]
          : (count == 1)            ? ((const double *) data)[i]
                                    : ((double *const *) data)[i][k];
  int *counts = (int *) malloc(sizeof(int) * (size_t) g->nranks);
  int *displs = (int *) malloc(sizeof(int) * (size_t) g->nranks);
  for (int r = 0; g->me == 0 && r < g->nranks; r++) {
    counts[r] = count * g->counts[r];
    displs[r] = count * g->displs[r];
  }
  double *received = (double *) malloc(sizeof(double) * (size_t) (count * g->natoms + 1));
  MPI_Gatherv(mine, count * g->nlocal, MPI_DOUBLE, received, counts, displs, MPI_DOUBLE, 0,
              MPI_COMM_WORLD);
  double *by_id = (double *) malloc(sizeof(double) * (size_t) (count * g->natoms + 1));
  for (int n = 0; g->me == 0 && n < g->natoms; n++)
    for (int k = 0; k < count; k++)
      by_id[count * (g->ids[n] - 1) + k] = received[count * n + k];
  free(mine);
  free(counts);
  free(displs);
  free(received);
  return by_id;
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

  Gathered g;
  gather_ids(lmp, &g);
  const int natoms = g.natoms;
  double *type = gather(lmp, &g, "type", 1, 1);
  double *x = gather(lmp, &g, "x", 3, 0);
  double *esph = gather(lmp, &g, "esph", 1, 0);
  double *cv = gather(lmp, &g, "cv", 1, 0);
  double *desph = gather(lmp, &g, "desph", 1, 0);
  double *rho = gather(lmp, &g, "rho", 1, 0);
  double *drho = gather(lmp, &g, "drho", 1, 0);
  double *v = gather(lmp, &g, "v", 3, 0);
  double *f = gather(lmp, &g, "f", 3, 0);

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
              i + 1, (int) type[i], x[3 * i], x[3 * i + 1], x[3 * i + 2], esph[i] / cv[i], desph[i], rho[i],
              drho[i], v[3 * i], v[3 * i + 1], v[3 * i + 2], f[3 * i], f[3 * i + 1], f[3 * i + 2]);
    fclose(out);
  }

  lammps_close(lmp);
  MPI_Finalize();
  return 0;
}

/* sph_dispatch.h: every combination of settings reaches the loop
   instantiated with exactly those values as template parameters, and a
   setting that is none of its list's values takes the list's last value.
   Built as C++11, as the 2021 release's plugin is. */
#include "sph_dispatch.h"

#include <cstdio>

using namespace LAMMPS_NS;

namespace {
struct Record {
  int chosen[3];
  int runs;
  template <int A, int B, int C> void run()
  {
    chosen[0] = A, chosen[1] = B, chosen[2] = C;
    runs++;
  }
};

int failures = 0;

void expect(const int *settings, const int *wanted)
{
  Record call = {{-1, -1, -1}, 0};
  SPHDispatch<SPHKernelKinds, SPHValues<5, 7, 9>, SPHFlag>::to(call, settings);
  const int same = call.runs == 1 && call.chosen[0] == wanted[0] && call.chosen[1] == wanted[1] &&
      call.chosen[2] == wanted[2];
  if (!same) {
    std::printf("settings %d %d %d: ran %d times with %d %d %d, wanted %d %d %d\n", settings[0],
                settings[1], settings[2], call.runs, call.chosen[0], call.chosen[1],
                call.chosen[2], wanted[0], wanted[1], wanted[2]);
    failures++;
  }
}
}    // namespace

int main()
{
  const int kernels[] = {SPHK_LUCY, SPHK_CUBIC, SPHK_QUINTIC, SPHK_WENDLAND};
  const int middles[] = {5, 7, 9};
  int combinations = 0;
  for (int kernel : kernels)
    for (int middle : middles)
      for (int flag = 0; flag < 2; flag++) {
        const int settings[] = {kernel, middle, flag};
        expect(settings, settings);
        combinations++;
      }
  // not in a list: that list's last value (a switch's default)
  const int stray[] = {SPHK_CUBIC, 8, 1}, stray_wanted[] = {SPHK_CUBIC, 9, 1};
  expect(stray, stray_wanted);
  const int stray_flag[] = {SPHK_LUCY, 5, 4}, stray_flag_wanted[] = {SPHK_LUCY, 5, 1};
  expect(stray_flag, stray_flag_wanted);
  std::printf("%s: %d combinations and 2 defaults, %d wrong\n", failures ? "FAIL" : "ok",
              combinations, failures);
  return failures ? 1 : 0;
}

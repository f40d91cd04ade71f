# Rayleigh-Benard convection: a fluid layer of height H = 1 between two no-slip,
# isothermal plates (bottom y = 0 at T = 1, top y = H at T = 0), periodic
# in x with width W (default 2H), Pr = 0.71, Boussinesq buoyancy. It starts
# in the conduction state T = 1 - y plus a small perturbation
#   eps sin(pi y) cos(2 pi x / W)
# whose kinetic energy decays below the onset and grows above it; the
# growth rate is 0.5 d ln(KE)/dt (analyse.py), the linear theory's that of
# the wavenumber a = 2 pi / W (tools/rb_linear.py; Ra_c = 1707.92 for
# W = 2H, 1955.81 for W = 1.5H).
# Units as examples/convection-cavity: H = 1, T_hot - T_cold = 1,
# rho = cv = k = 1 (thermal diffusivity 1, time in H^2/alpha); viscosity Pr,
# expansion 1, gravity Ra Pr, so that Ra = g beta dT H^3 / (nu alpha);
# T0 = 0.5. Walls: layers of wall particles below y = 0 and above y = H,
# Adami no-slip walls for the flow, their velocity mirrored across the
# plates (fix sph/wall/adami ... surface), Dirichlet walls mirrored across
# them for the heat (fix sph/wall/dirichlet ... surface).
#
#   lmp -in in.rb -var plugin /path/to/sphthermalplugin.so -var ra 3000
# Variables: ra, pr, n (particles per H), width (W / H; W n must be an
#   integer), kernel, hdx (h / dx), eps (perturbation amplitude), tend (end
#   time), kemax (or stop when the kinetic energy exceeds it: the end of the
#   linear stage), cfac (c0 = cfac sqrt(Ra Pr / 2)), c0min, bg (background
#   pressure / (rho0 c0^2)), delta (density diffusion of the pair), pform
#   (its pressure form), cac (acoustic coefficient of fix sph/dt/reset), init
#   (hydrostatic: the density of the conduction state's pressure; uniform:
#   rho0 everywhere), every (thermo), dump (yes: write the fluid to the
#   file out at the end), t0 (T0 of fix sph/boussinesq: 0.5 or layers),
#   gradient (correction of the flow pair), conduction (keywords of the heat
#   pair; none: the package's default, the plain operator at the onset,
#   unshifted, and 'correction consistent' with shifting), shift (skillen coefficient, 0: none), continuity (of the shift),
#   hold (of fix sph/boussinesq: yes, the package's default in a closed
#   cell, holds the fluid's volume sum m / rho; no: the continuity
#   equation's, which lets the mean density rise), jitter
#   (random initial displacement of the fluid particles / dx; 0, the
#   default: none), seed (its random seed), noslip (surface: the walls'
#   velocity from the fluid's across the plates, the default; shepard:
#   Adami's mean of the fluid near each wall particle, for comparison).
# settings = onset (the defaults below) or convection: above onset, to a
#   steady state (t = 0.8), with the flagship cavity's settings (without
#   the background pressure particles entered the plates at 10 and 16 per H
#   and lost the run at 20 and 30), and T0 by layers, so that the conduction
#   state is not compressed and the run starts from the rest density
#   ('run.sh nu').
# Defaults and why (README.md): cfac 5, so that c0^2 = 100 times the
#   pressure difference of the conduction state, g/8 (density range 0.9 %);
#   at cfac 10 the run goes unstable with cac 0.1 (stable with cac 0.05).
#   bg 0: a background pressure slows the growth (it stiffens the particle
#   lattice: bg 0.01 at cfac 5 gave sigma 5.9 instead of 7.5 at Ra 3000).
#   delta 0: the density diffusion slowed the growth of the perturbation,
#   measured with Molteni's form, which flattened the hydrostatic density of
#   the conduction state (the pair's Fourtakas form now reads the buoyancy).

variable plugin  index ../../build/sphthermalplugin.so
variable settings index onset
if "${settings} == convection" then &
  "variable tend index 0.8" "variable kemax index 1e30" "variable delta index 0.1" &
  "variable init index uniform" "variable t0 index layers" "variable gradient index gradient" &
  "variable shift index 2" "variable every index 200" "variable bg index 0.1" &
elif "${settings} != onset" &
  "print 'ERROR: settings ${settings}: onset or convection'" "quit 1"
variable ra      index 3000
variable pr      index 0.71
variable n       index 20
variable width   index 2.0
variable kernel  index wendland
variable hdx     index 2.0
variable eps     index 1e-2
variable tend    index 0.3
variable kemax   index 1.0
variable cfac    index 5
variable c0min   index 50
variable bg      index 0.0
variable eta     index 0.01
variable pform   index averaged
variable cac     index 0.1
variable delta   index 0.0
variable init    index hydrostatic
variable every   index 100
variable out     index rb.dump
variable dump    index no
variable t0      index 0.5
variable gradient index none
variable conduction index ""
variable shift   index 0
variable continuity index no
variable hold    index yes
variable jitter  index 0.0
variable seed    index 12345
variable noslip  index surface

variable has_plugin equal is_file(${plugin})
if "${has_plugin}" then "plugin load ${plugin}" &
   else "print 'NOTE: no plugin file ${plugin}: USER-SPHTHERMAL must be built into this LAMMPS'"

units           si
dimension       2
atom_style      sph
boundary        p f p
comm_modify     vel yes

variable        dx equal 1.0/${n}
variable        nw equal round(${width}*${n})
if "$(abs(v_nw-v_width*v_n) > 1e-9)" then "print 'width * n = $(v_width*v_n) must be an integer'" quit
variable        g equal ${ra}*${pr}
# the buoyant pressure scale g beta dT H / 2 = Ra Pr / 2 (the conduction
# state's pressure varies by g/8 over the layer): c0^2 = cfac^2 Ra Pr / 2
variable        c0a equal ${cfac}*sqrt(v_g/2.0)
# (LAMMPS 29Sep2021 has no ternary(): an if)
variable        c0 equal ${c0min}
if "$(v_c0a) > ${c0min}" then "variable c0 delete" "variable c0 equal ${c0a}"
variable        qmax equal 2
if "${kernel} == lucy" then "variable qmax delete" "variable qmax equal 1"
if "${kernel} == quintic" then "variable qmax delete" "variable qmax equal 3"
variable        cut equal v_qmax*v_hdx*v_dx
variable        layers equal ceil(v_qmax*v_hdx)

lattice         sq ${dx} origin 0.5 0.5 0.0
region          box block 0 ${nw} $(-v_layers) $(v_n+v_layers) -0.5 0.5
create_box      2 box
create_atoms    1 region box
# the layer: its boundary y = 0 and y = H is the plates' surface
region          layer block INF INF 0 ${n} INF INF
group           fluid region layer
group           wall subtract all fluid
set             group wall type 2
region          below block INF INF INF 0 INF INF
region          above block INF INF ${n} INF INF INF
group           hot region below
group           cold region above
# optional random displacement of the fluid particles (a fraction of dx)
# off the lattice (a stability check)
if "${jitter} > 0.0" then &
  "displace_atoms fluid random $(v_jitter*v_dx) $(v_jitter*v_dx) 0.0 ${seed} units box"

fix             materials all sph/materials type * conductivity constant 1.0 cv 1.0 &
                viscosity constant ${pr} expansion 1.0 &
                eos linear ${c0} background $(v_bg*v_c0^2) rho0 1.0
sph/set         all materials spacing ${dx} temperature 0.5
variable        Tinit atom 1.0-y+${eps}*sin(PI*y)*cos(2.0*PI*x/${width})
sph/set         fluid temperature v_Tinit
sph/set         hot temperature 1.0
sph/set         cold temperature 0.0
# hydrostatic start: the conduction state's pressure, dp/dy = g (1/2 - y)
# (rho = 1), zero on average over the layer, gives the density
# 1 + (y/2 - y^2/2 - 1/12) g / c0^2 (mass conserved)
variable        rhoinit atom 1.0+(y/2.0-y*y/2.0-1.0/12.0)*v_g/(v_c0*v_c0)
if "${init} == hydrostatic" then "set group fluid sph/rho v_rhoinit"

pair_style      hybrid/overlay sph/harmonic/visc ${kernel} ${cut} eta ${eta} delta ${delta} pressure ${pform} &
                correction ${gradient} sph/cleary/heat same eta ${eta} ${conduction}
pair_coeff      * * sph/harmonic/visc
pair_coeff      * * sph/cleary/heat
neighbor        $(0.2*v_dx) bin
neigh_modify    delay 0 every 1 check yes exclude type 2 2

if "${noslip} == surface" then "fix flow_walls wall sph/wall/adami surface layer" &
   elif "${noslip} == shepard" "fix flow_walls wall sph/wall/adami" &
   else "print 'ERROR: noslip ${noslip}: surface or shepard'" "quit 1"
fix             hot hot sph/wall/dirichlet 1.0 surface layer
fix             cold cold sph/wall/dirichlet 0.0 surface layer
fix             buoyancy fluid sph/boussinesq ${t0} gravity 0.0 -${g} 0.0 hold ${hold}
fix             integrate fluid sph
if "${shift} > 0" then "fix shift fluid sph/shift skillen ${shift} continuity ${continuity}"
fix             dt fluid sph/dt/reset 1 acoustic ${cac}

# Nu of the plates from the heat they give (hot) and take up (cold): 1 in
# the conduction state; the area of each plate is the width
compute         nu_hot hot sph/nusselt hot 1.0 1.0 1.0 area ${width}
compute         nu_cold cold sph/nusselt cold -1.0 1.0 1.0 area ${width}
variable        nu_hot equal c_nu_hot[1]
variable        nu_cold equal c_nu_cold[1]
# kinetic energy of the fluid, 1/2 sum m v^2 (m = rho0 dx^2: per unit depth)
compute         ke fluid ke
variable        vy2 atom vy*vy
compute         vy2max fluid reduce max v_vy2
variable        vymax equal sqrt(c_vy2max)
compute         rho fluid sph/rho/atom
compute         rhomin fluid reduce min c_rho
compute         rhomax fluid reduce max c_rho
compute         rhoave fluid reduce ave c_rho
# the fluid's volume, sum m / rho (fix sph/boussinesq holds it)
variable        volume atom mass/c_rho
compute         volume fluid reduce sum v_volume
thermo_style    custom step time dt c_ke v_vymax c_nu_hot[1] c_nu_cold[1] c_rhomin c_rhomax c_rhoave &
                c_volume elapsed cpuremain
thermo_modify   format float %.10g
thermo          ${every}
print           "Ra = ${ra}, Pr = ${pr}, width = ${width}, ${nw} x ${n} fluid particles, c0 = $(v_c0:%.4g), g = $(v_g:%.6g), eps = ${eps}, init = ${init}"
run             0
variable        reached equal (time>=${tend})||(c_ke>${kemax})
fix             stop fluid halt 10 v_reached == 1 error continue
run             100000000
# LAMMPS 29Sep2021 gives no thermo output on the step fix halt stops at, so
# the computes of the final line are current only after a thermo output:
# run 0; the dump also needs c_T and c_rho of this step
if "${dump} == yes" then "compute T fluid sph/t/atom" &
   "compute Tsum fluid reduce sum c_T" &
   "thermo_style custom step time dt c_ke v_vymax c_nu_hot[1] c_nu_cold[1] c_rhomin c_Tsum c_volume"
run             0 post no
if "${dump} == yes" then &
   "write_dump fluid custom ${out} id x y vx vy c_T c_rho modify sort id format float %.15g"
print           "final: Ra = ${ra} t = $(time:%.5f) steps = $(step) KE = $(c_ke:%.6e) vymax = $(v_vymax:%.6e) Nu_hot = $(v_nu_hot:%.6f) Nu_cold = $(v_nu_cold:%.6f) volume = $(c_volume:%.15g)"

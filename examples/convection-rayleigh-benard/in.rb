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
#   linear stage), every (thermo), dump (yes: write the fluid to the file
#   out at the end), jitter (random initial displacement of the fluid
#   particles / dx; 0: none), seed (its random seed).
# Every numerical setting is the package's default; these variables vary
#   them for a study: eos (the equation of state's speed of sound and
#   keywords, 'auto': the package's, from the buoyancy's compression),
#   flow and heat (more keywords of pair sph/harmonic/visc and
#   sph/cleary/heat), dtreset (keywords of fix sph/dt/reset), t0 (T0 of fix
#   sph/boussinesq: layers, so that the conduction state feels no buoyancy
#   and the run starts at rest at rho0; or a temperature), shift (yes: fix
#   sph/shift with the keywords shiftargs), hold (of fix sph/boussinesq),
#   noslip (surface: the walls' velocity from the fluid's across the
#   plates; shepard: Adami's mean of the fluid near each wall particle).
# settings = onset (unshifted) or convection: above onset, to a steady
#   state (t = 0.8), the particles shifted, with which the package corrects
#   the flow pair's pressure gradient, as in the flagship cavity ('run.sh
#   nu').

variable plugin  index ../../build/sphthermalplugin.so
variable settings index onset
if "${settings} == convection" then &
  "variable tend index 0.8" "variable kemax index 1e30" "variable shift index yes" &
  "variable every index 200" &
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
variable every   index 100
variable out     index rb.dump
variable dump    index no
variable jitter  index 0.0
variable seed    index 12345
variable eos     index auto
variable flow    index ""
variable heat    index ""
variable dtreset index ""
variable t0      index layers
variable shift   index no
variable shiftargs index ""
variable hold    index yes
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
                eos linear ${eos} rho0 1.0
sph/set         all materials spacing ${dx} temperature 0.5
variable        Tinit atom 1.0-y+${eps}*sin(PI*y)*cos(2.0*PI*x/${width})
sph/set         fluid temperature v_Tinit
sph/set         hot temperature 1.0
sph/set         cold temperature 0.0

pair_style      hybrid/overlay sph/harmonic/visc ${kernel} ${cut} ${flow} sph/cleary/heat same ${heat}
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
if "${shift} == yes" then "fix shift fluid sph/shift ${shiftargs}"
fix             dt fluid sph/dt/reset 1 ${dtreset}

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
print           "Ra = ${ra}, Pr = ${pr}, width = ${width}, ${nw} x ${n} fluid particles, g = $(v_g:%.6g), eps = ${eps}"
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

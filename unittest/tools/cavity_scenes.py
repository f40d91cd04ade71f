"""Input blocks of the unit-cavity scenes that the convection and robust
checks share (one place, imported from unittest/tools on the tests'
PYTHONPATH)."""

# the unit cavity of lattice particles, 0.1 apart, walls three rows thick
LATTICE = """plugin load {plugin}
units           si
dimension       2
atom_style      sph
boundary        f f p
atom_modify     map array
lattice         sq 0.1 origin 0.5 0.5 0.0
region          box block -3 13 -3 13 -0.5 0.5
create_box      2 box
create_atoms    1 region box
region          cavity block 0 1 0 1 INF INF units box
group           fluid region cavity
group           wall subtract all fluid
set             group wall type 2
"""
JITTER = """variable        jx atom 0.025*sin(37.0*x+11.0*y)
variable        jy atom 0.025*cos(23.0*x-29.0*y)
displace_atoms  fluid move v_jx v_jy 0.0 units box
"""
CONDUCTION = """fix             materials all sph/materials type * conductivity constant 1.0 cv 2.0 rho0 1.0
sph/set         all materials spacing 0.1 temperature 0.0
pair_style      sph/cleary/heat quintic 0.3
pair_coeff      * *
neigh_modify    exclude type 2 2
"""
BOX = LATTICE + JITTER + CONDUCTION

# a linear field between a hot (x = 0) and a cold (x = 1) mirror wall, the
# other two adiabatic, and the Nusselt numbers of both
NUSSELT_WALLS = """region          left block INF 0 INF INF INF INF units box
region          right block 1 INF INF INF INF INF units box
group           hot region left
group           cold region right
group           held union hot cold
group           sides subtract wall held
variable        Tlin atom 1.0-x
sph/set         fluid temperature v_Tlin
fix             hot hot sph/wall/dirichlet 1.0 surface cavity
fix             cold cold sph/wall/dirichlet 0.0 surface cavity
fix             adiabatic sides sph/wall/adiabatic surface cavity
compute         nu_hot hot sph/nusselt hot 1.0 1.0 1.0
compute         nu_cold cold sph/nusselt cold -1.0 1.0 type 1
"""


#!/bin/bash
# Writes the tied-contact patch test decks of this folder (run once; the decks are kept in
# git): the V5 geometry (docs/verification/v5_v6.md) with the contact pair replaced by a TIE.
set -eu
cd "$(dirname "$0")"
write() {  # name nu_upper slave master comment
  local name=$1 n=$2 slave=$3 master=$4 comment=$5
  cat > "$name.dck" <<DECK
==================================================================
 Tied contact patch test (docs/contact.md, "Tied contact"): the V5 geometry with a TIE.
 Two stacked blocks with NON-matching meshes, uniform pressure p = 100 on the top.
 Lower block [0,1] x [0,1] x [0,0.5], 4 x 4 x 2 HEX8; upper block [0,1] x [0,1] x [0.5,1],
 $n x $n x 2 HEX8. Both E = 1.0e5, nu = 0.3.
 Supports: z = 0: u_z = 0; x = 0 faces of both blocks: u_x = 0; y = 0 faces of both blocks:
 u_y = 0. The upper block is held in z by the tie only.
 Exact solution: uniaxial stress sigma_zz = -p in both blocks (linear displacements, which
 the tie's constraint u_s = sum N_a u_a reproduces): bond pressure p at every slave node.
 $comment
 units: consistent (e.g. N, mm, MPa)
==================================================================
---------------------------------------------------------PROBLEM TYP
PROBLEMTYP   Structure
--------------------------------------------------------------STATIC
KINTYP       Geo_Lin
MAXITER      30
TOLRESID     1.0e-8
TOLDISP      1.0e-8
-----------------------------------------------------------MATERIALS
MAT 1 MAT_Struct_LinearElastic YOUNG 1.0e5 NUE 0.3
----------------------------------------------------------MESH BLOCK
BLOCK lower ORIGIN 0 0 0   SIZE 1 1 0.5 DIVISIONS 4 4 2
BLOCK upper ORIGIN 0 0 0.5 SIZE 1 1 0.5 DIVISIONS $n $n 2
--------------------------------------------------STRUCTURE ELEMENTS
SET lower SOLID HEX8 MAT 1
SET upper SOLID HEX8 MAT 1
------------------------------------------------DIRICHLET CONDITIONS
SET lower_zmin DOF 0 0 1 VAL 0.0 0.0 0.0
SET lower_xmin DOF 1 0 0 VAL 0.0 0.0 0.0
SET lower_ymin DOF 0 1 0 VAL 0.0 0.0 0.0
SET upper_xmin DOF 1 0 0 VAL 0.0 0.0 0.0
SET upper_ymin DOF 0 1 0 VAL 0.0 0.0 0.0
--------------------------------------------------NEUMANN CONDITIONS
SURF upper_zmax PRESSURE 100.0
--------------------------------------------------CONTACT CONDITIONS
TIE 1 SLAVE $slave MASTER $master
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP 1 CONTROL Load
-------------------------------------------------------------RESULTS
VTK Yes  LISTING Yes
-----------------------------------------------------------------END
DECK
}
write tie_u3_slave_upper 3 upper_zmin lower_zmax "Tie: slave = upper (coarse, 3 x 3) bottom, master = lower top."
write tie_u3_slave_lower 3 lower_zmax upper_zmin "Tie: slave = lower (fine, 4 x 4) top, master = upper bottom."
write tie_u5_slave_upper 5 upper_zmin lower_zmax "Tie: slave = upper (fine, 5 x 5) bottom, master = lower top."
write tie_u5_slave_lower 5 lower_zmax upper_zmin "Tie: slave = lower (coarse, 4 x 4) top, master = upper bottom."

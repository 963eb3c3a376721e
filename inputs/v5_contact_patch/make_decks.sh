#!/bin/bash
# Writes the V5 contact patch test decks of this folder (run once; the decks are kept in git).
# Variants: upper mesh NU x NU (3 or 5), slave side, PASSES 1|2, law (frictionless or Coulomb).
set -eu
cd "$(dirname "$0")"
write() {  # name nu_upper slave master passes friction_words comment
  local name=$1 n=$2 slave=$3 master=$4 passes=$5 friction=$6 comment=$7
  cat > "$name.dck" <<DECK
==================================================================
 V5: contact patch test (Taylor & Papadopoulos, Comput. Methods Appl. Mech. Engrg. 1991)
 Two stacked blocks with NON-matching meshes, uniform pressure p = 100 on the top.
 Lower block [0,1] x [0,1] x [0,0.5], 4 x 4 x 2 HEX8; upper block [0,1] x [0,1] x [0.5,1],
 $n x $n x 2 HEX8. Both E = 1.0e5, nu = 0.3 (same material: equal lateral expansion).
 Supports (symmetric rollers, no rigid mode): z = 0: u_z = 0; x = 0 faces of both blocks:
 u_x = 0; y = 0 faces of both blocks: u_y = 0. The upper block is held in z by contact only.
 Exact solution: uniaxial stress sigma_zz = -p in both blocks, contact pressure p everywhere.
 $comment
 Contact: SLAVE $slave MASTER $master, PASSES $passes, EPSN 1e8 (penetration p/EPSN = 1e-6
 against the elastic shortening p H/E = 1e-3), GAPTOL 1e-6 (touching at the start).
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
PAIR 1 SLAVE $slave MASTER $master EPSN 1.0e8 GAPTOL 1.0e-6 PASSES $passes $friction
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP 1 CONTROL Load
-------------------------------------------------------------RESULTS
VTK Yes  LISTING Yes
-----------------------------------------------------------------END
DECK
}
fl="LAW Frictionless"
co="EPST 1.0e8 MU 0.3"
write v5_u3_slave_upper_1pass 3 upper_zmin lower_zmax 1 "$fl" "Frictionless. One pass, slave = upper (coarse, 3 x 3) bottom."
write v5_u3_slave_lower_1pass 3 lower_zmax upper_zmin 1 "$fl" "Frictionless. One pass, slave = lower (fine, 4 x 4) top."
write v5_u3_2pass            3 upper_zmin lower_zmax 2 "$fl" "Frictionless. Two passes (both surfaces slave and master)."
write v5_u5_slave_upper_1pass 5 upper_zmin lower_zmax 1 "$fl" "Frictionless. One pass, slave = upper (fine, 5 x 5) bottom."
write v5_u5_slave_lower_1pass 5 lower_zmax upper_zmin 1 "$fl" "Frictionless. One pass, slave = lower (coarse, 4 x 4) top."
write v5_u5_2pass            5 upper_zmin lower_zmax 2 "$fl" "Frictionless. Two passes (both surfaces slave and master)."
write v5_u3_2pass_coulomb    3 upper_zmin lower_zmax 2 "$co" "Coulomb MU 0.3, EPST 1e8: same nu in both blocks, so no tangential traction and no slip."
write v5_u3_1pass_coulomb    3 upper_zmin lower_zmax 1 "$co" "Coulomb MU 0.3, EPST 1e8: same nu in both blocks, so no tangential traction and no slip."
write v5_u4_matching_1pass   4 upper_zmin lower_zmax 1 "$fl" "Control: MATCHING meshes (4 x 4 on 4 x 4), frictionless, one pass: must pass exactly."
sed "s/EPSN 1e8 (penetration p\/EPSN = 1e-6/EPSN 1e10 (penetration p\/EPSN = 1e-8/; s/EPSN 1.0e8 GAPTOL/EPSN 1.0e10 GAPTOL/" v5_u3_2pass.dck > v5_u3_2pass_eps1e10.dck
sed "s/EPSN 1e8 (penetration p\/EPSN = 1e-6/EPSN 1e10 (penetration p\/EPSN = 1e-8/; s/EPSN 1.0e8 GAPTOL/EPSN 1.0e10 GAPTOL/" v5_u3_2pass_coulomb.dck > v5_u3_2pass_coulomb_eps1e10.dck
# Augmented Lagrangian (METHOD Augmented): the multipliers are augmented until every
# penetration is below PENTOL, so the result no longer depends on EPSN (docs/contact.md).
augmented() {  # source target epsn pentol
  sed "s/EPSN 1e8 (penetration p\/EPSN = 1e-6/METHOD Augmented, EPSN $3, PENTOL $4 (penetration at most $4/; s/EPSN 1.0e8 GAPTOL/METHOD Augmented EPSN $3 PENTOL $4 GAPTOL/" "$1.dck" > "$2.dck"
}
augmented v5_u3_2pass v5_u3_2pass_augmented 1.0e8 1.0e-11
augmented v5_u3_2pass v5_u3_2pass_augmented_eps1e7 1.0e7 1.0e-11
augmented v5_u3_slave_upper_1pass v5_u3_slave_upper_1pass_augmented 1.0e8 1.0e-11

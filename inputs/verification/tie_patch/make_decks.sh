#!/bin/bash
# Writes the tied-contact patch test decks of this folder (run once; the decks are kept in
# git) from the V5 contact patch decks (inputs/v5_contact_patch, docs/verification/v5_v6.md):
# the same blocks, supports and load, the contact pair replaced by a TIE of the same slave and
# master surfaces.
set -eu
cd "$(dirname "$0")"
v5=../../v5_contact_patch
tie() {  # v5_deck tie_deck
  sed -e 's/^ V5: contact patch test (Taylor & Papadopoulos, Comput. Methods Appl. Mech. Engrg. 1991)/ Tied contact patch test (docs\/contact.md, "Tied contact"): the V5 contact patch test\n (Taylor \& Papadopoulos, Comput. Methods Appl. Mech. Engrg. 1991) with a TIE instead of contact./' \
      -e 's/^ Exact solution: uniaxial stress sigma_zz = -p in both blocks, contact pressure p everywhere./ Exact solution: uniaxial stress sigma_zz = -p in both blocks (linear displacements, which the\n tie'"'"'s constraint reproduces), bond pressure p at every slave node./' \
      -e 's/held in z by contact only/held in z by the tie only/' \
      -e '/^ Frictionless\. One pass/d' -e '/^ Contact: SLAVE/d' -e '/^ against the elastic shortening/d' \
      -e 's/^PAIR 1 SLAVE \([a-z_]*\) MASTER \([a-z_]*\) .*/TIE 1 SLAVE \1 MASTER \2/' \
      "$v5/$1.dck" > "$2.dck"
}
tie v5_u3_slave_upper_1pass tie_u3_slave_upper
tie v5_u3_slave_lower_1pass tie_u3_slave_lower
tie v5_u5_slave_upper_1pass tie_u5_slave_upper
tie v5_u5_slave_lower_1pass tie_u5_slave_lower

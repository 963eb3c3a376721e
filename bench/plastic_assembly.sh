#!/bin/bash
# plastic_assembly.sh [N] [REPEATS]: the cost of plasticity in the assembly.
#
# For an N x N x N cube of unit HEX8 elements (default N = 20, 8000 elements) and each element
# variant (HEX8, HEX8-EAS9) and kinematics (Geo_Lin, Tot_Lagr), times REPEATS assemblies
# (default 5) of fint + tangent with bench/p1_assembly_timer:
#   elastic   MAT_Struct_LinearElastic (Geo_Lin) / MAT_Struct_StVenantKirchhoff (Tot_Lagr), u = 0
#   plastic   MAT_3DMisesPlastic, uniform strain u_x = 0.01 x (5 x the yield strain: every
#             integration point returns to the yield surface in every assembly)
# LAWS (environment, default "mises") adds the soil laws: "mises mohr_coulomb drucker_prager".
# Soil: E = 1e5, nu = 0.3, c = 10, phi = 30 degrees, psi = 10 degrees (non-associated, the
# unsymmetric tangent), simple shear u_x = 0.01 z (gamma_xz = 0.01: elastically
# sigma_1 = -sigma_3 = 385, sigma_2 = 0, twenty times the shear strength 2 c cos(phi) = 17.3:
# every point returns onto Mohr-Coulomb's main plane, resp. the Drucker-Prager cone); the
# elastic reference is the deck's linear elastic law as for von Mises.
# and prints elements per CPU second and the ratio plastic / elastic (docs/performance.md,
# "Plastic assembly"). Rows are appended to bench/results/plastic_assembly.csv.
# Needs the timer: cmake --build build --target p1_assembly_timer (BUILD=build by default).
set -eu
n=${1:-20}; repeats=${2:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
timer=${P1_ASSEMBLY_TIMER:-$root/${BUILD:-build}/bench/p1_assembly_timer}
[ -x "$timer" ] || { echo "plastic_assembly.sh: no timer at $timer (cmake --build build --target p1_assembly_timer)" >&2; exit 2; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
csv=$root/bench/results/plastic_assembly.csv
mkdir -p "$(dirname "$csv")"
[ -f "$csv" ] || echo "date,n,variant,kinematics,material,strain,elements,cpu_seconds,elements_per_cpu_second,load1" > "$csv"

deck() {  # deck NAME KINTYP LAW EAS
    local law_line
    case $3 in
        plastic) law_line="MAT 1 MAT_3DMisesPlastic YOUNG 210000.0 NUE 0.3 SIGY 420.0 HARD 75000.0" ;;
        mohr_coulomb) law_line="MAT 1 MAT_3DMohrCoulomb YOUNG 1.0e5 NUE 0.3 COHESION 10.0 PHI 30.0 PSI 10.0" ;;
        drucker_prager) law_line="MAT 1 MAT_3DDruckerPrager YOUNG 1.0e5 NUE 0.3 COHESION 10.0 PHI 30.0 PSI 10.0" ;;
        elastic) if [ "$2" = Tot_Lagr ]; then law_line="MAT 1 MAT_Struct_StVenantKirchhoff YOUNG 210000.0 NUE 0.3"
                 else law_line="MAT 1 MAT_Struct_LinearElastic YOUNG 210000.0 NUE 0.3"; fi ;;
    esac
    cat > "$work/$1.dck" <<DECK
---------------------------------------------------------PROBLEM TYP
PROBLEMTYP   Structure
--------------------------------------------------------------STATIC
KINTYP       $2
-----------------------------------------------------------MATERIALS
$law_line
----------------------------------------------------------MESH BLOCK
BLOCK cube ORIGIN 0 0 0 SIZE $n $n $n DIVISIONS $n $n $n
--------------------------------------------------STRUCTURE ELEMENTS
SET cube SOLID HEX8 MAT 1 EAS $4
------------------------------------------------DIRICHLET CONDITIONS
SET cube_xmin DOF 1 1 1 VAL 0.0 0.0 0.0
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP 1
-----------------------------------------------------------------END
DECK
}

printf '%-15s %-10s %-9s %14s %14s %7s\n' law variant kinematics elastic_el/s plastic_el/s ratio
for law in ${LAWS:-mises}; do
  material=$law; [ "$law" = mises ] && material=plastic
  plastic_args="0.01"; [ "$law" = mises ] || plastic_args="0 0.01"
  for eas in 0 9; do
    variant=HEX8; [ $eas -gt 0 ] && variant=HEX8-EAS$eas
    for kin in Geo_Lin Tot_Lagr; do
        declare -A rate
        for kind in elastic $material; do
            strain=0; [ $kind = $material ] && strain=$plastic_args
            deck "$kind" "$kin" "$kind" "$eas"
            out=$("$timer" "$work/$kind.dck" "$repeats" $strain)
            cpu=$(awk '/assembly_cpu_seconds/ { print $3 }' <<< "$out")
            rate[$kind]=$(awk '/elements_per_cpu_second/ && !/kernel/ { print $3 }' <<< "$out")
            echo "$(date -u +%FT%TZ),$n,$variant,$kin,$kind,${strain// /:},$((n*n*n)),$cpu,${rate[$kind]},$(cut -d' ' -f1 /proc/loadavg)" >> "$csv"
        done
        printf '%-15s %-10s %-9s %14.0f %14.0f %7.2f\n' "$law" "$variant" "$kin" "${rate[elastic]}" "${rate[$material]}" \
            "$(awk -v p="${rate[$material]}" -v e="${rate[elastic]}" 'BEGIN { print p / e }')"
    done
  done
done

//! The promise under attack, round three (issue 24): one test per finding,
//! each of which returned a wrong number, aborted or hung before its fix.

use layered_contact::indenter::FlatPunch;
use layered_contact::solver::{ContactSolver, SolverParams};
use layered_contact::substrate::Base;
use layered_contact::{Boundary, Error, Grid, Material, Substrate};

fn solver(substrate: &Substrate, grid: &Grid) -> Result<ContactSolver, Error> {
    ContactSolver::new(substrate, grid, Boundary::Isolated, SolverParams::default())
}

fn punch_force(substrate: &Substrate, grid: &Grid, radius: f64, depth: f64) -> f64 {
    let punch = FlatPunch::new(radius).unwrap();
    let (solution, _) = solver(substrate, grid)
        .unwrap()
        .solve_depth(&punch, depth, None, &mut ())
        .unwrap();
    solution.force
}

/// Finding 1: a coating 1e3 to 1e7 times stiffer than its base and much
/// thinner than a cell (100 nm of DLC on a polymer, 0.1 mm cells) returned
/// punch forces 44 to 1e27 times below the bare base's. Its Green's
/// function varies over the coating's membrane and bending lengths, far
/// beyond the 512 thicknesses the remainder was tabulated to. Now the table
/// goes on to 8192 thicknesses where the asymptotics do not yet hold, and a
/// grid that reaches further is refused, naming its diagonal over the
/// thickness. Reference: a stiffer body carries more, so the force lies
/// between the bare base's and the coating material's half-space's, and
/// grows with the coating's modulus.
#[test]
fn f1_thin_stiff_coatings_lie_between_their_materials_or_are_refused() {
    let base = Material::new(3e8, 0.3).unwrap();
    let grid = Grid::new(16, 16, 1e-4).unwrap();
    let (radius, depth) = (5e-4, 1e-6);
    let soft = punch_force(&Substrate::half_space(base), &grid, radius, depth);
    // The grid's diagonal, (16.5 sqrt 2) Delta, over 100 nm.
    let diagonal = 16.5 * 2f64.sqrt() * 1e-4 / 1e-7;
    let mut previous = soft;
    for ratio in [1e3, 1e5, 1e7] {
        let coating = Material::new(3e8 * ratio, 0.3).unwrap();
        let thin = Substrate::layer_on_elastic_base(coating, 1e-7, base).unwrap();
        let stacked = Substrate::stack(&[(coating, 1e-7), (base, 1e-3)], Base::Rigid).unwrap();
        for refused in [thin, stacked] {
            match solver(&refused, &grid) {
                Err(Error::InvalidParameter { value, .. }) => {
                    assert!((value / diagonal - 1.0).abs() < 1e-12, "{value}")
                }
                other => panic!("{ratio:e}: {:?}", other.map(|_| ())),
            }
        }
        // 2 um: the grid spans 1167 thicknesses, inside the table.
        let covered = Substrate::layer_on_elastic_base(coating, 2e-6, base).unwrap();
        let force = punch_force(&covered, &grid, radius, depth);
        let stiff = punch_force(&Substrate::half_space(coating), &grid, radius, depth);
        assert!(previous < force && force < stiff, "{ratio:e}: {previous} {force} {stiff}");
        previous = force;
    }
}

/// Finding 2: a nearly incompressible film thinner than a cell on a support
/// that acts as rigid but is not a rigid base (an elastic base 1e12 times
/// stiffer, or a stiff layer under it in a stack on a rigid base) passed
/// the film check, which looked only at a rigid base and a stack's total
/// thickness, and returned 97 N and 864 N against the squeeze film's
/// 1.4e-3 N. The check now weighs the film against its support's
/// compliance at the cell's wavenumber, whatever the support. Reference: on
/// a support a thousand times stiffer (still resolvable) the same film is
/// accepted, and a punch on it carries the bare support's force: the film's
/// squeeze-film compliance is about 1e-8 of the support's here, and the
/// film spreads each cell's load over about `h`, which moves cell-centre
/// collocation by `O(h / Delta) = 1e-3`.
#[test]
fn f2_incompressible_films_on_rigid_like_supports_are_refused() {
    let rubber = Material::new(1e6, 0.5).unwrap();
    let grid = Grid::new(16, 16, 1e-4).unwrap();
    for ratio in [1e-2, 1e-3] {
        let h = ratio * grid.spacing();
        let hard = Material::new(1e18, 0.3).unwrap();
        let bodies = [
            Substrate::layer_on_elastic_base(rubber, h, hard).unwrap(),
            Substrate::stack(&[(rubber, h), (hard, 1e-3)], Base::Rigid).unwrap(),
        ];
        for body in bodies {
            match solver(&body, &grid) {
                Err(Error::InvalidParameter { value, .. }) => {
                    assert!((value / ratio - 1.0).abs() < 1e-9, "{value}")
                }
                other => panic!("{ratio}: {:?}", other.map(|_| ())),
            }
        }
    }
    let glassy = Material::new(1e9, 0.3).unwrap();
    let film = Substrate::layer_on_elastic_base(rubber, 1e-7, glassy).unwrap();
    let (radius, depth) = (5e-4, 1e-6);
    let coated = punch_force(&film, &grid, radius, depth);
    let bare = punch_force(&Substrate::half_space(glassy), &grid, radius, depth);
    assert!((coated / bare - 1.0).abs() < 1e-3, "{coated} {bare}");
}

//! Data out for lab reports: the totals' time series, every disc's values
//! and the collision ledger as CSV files, written atomically into the
//! output folder the window names. Discs are numbered from 1, as the
//! window numbers them.

use super::totals::Sample;
use crate::app::numbers::disc_number;
use crate::files::write_atomically;
use impulse::ledger::Ledger;
use impulse::World;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The totals against time.
pub fn totals_csv(samples: &[Sample]) -> String {
    let mut out = String::from(
        "time_s,px_kg_m_s,py_kg_m_s,kinetic_energy_j,rotational_energy_j,angular_momentum_kg_m2_s\n",
    );
    for s in samples {
        let _ = writeln!(
            out,
            "{},{},{},{},{},{}",
            s.time,
            s.momentum.x,
            s.momentum.y,
            s.kinetic_energy,
            s.rotational_energy,
            s.angular_momentum
        );
    }
    out
}

/// Every disc now.
pub fn particles_csv(world: &World) -> String {
    let mut out = String::from(
        "disc,x_m,y_m,vx_m_s,vy_m_s,mass_kg,radius_m,px_kg_m_s,py_kg_m_s,kinetic_energy_j,\
         spin_rad_s,rotational_energy_j,angular_momentum_kg_m2_s\n",
    );
    for (k, p) in world.particles.iter().enumerate() {
        let m = p.momentum();
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{},{},{},{}",
            disc_number(k),
            p.pos.x,
            p.pos.y,
            p.vel.x,
            p.vel.y,
            p.mass,
            p.radius,
            m.x,
            m.y,
            p.kinetic_energy(),
            p.spin,
            p.rotational_energy(),
            p.angular_momentum()
        );
    }
    out
}

/// The collision ledger: per collision, both discs' momentum, kinetic
/// energy, spin and rotational energy before and after, and the change of
/// the totals.
pub fn ledger_csv(ledger: &Ledger) -> String {
    let mut out = String::from(
        "time_s,disc_a,disc_b,normal_x,normal_y,\
         pa_before_x,pa_before_y,pa_after_x,pa_after_y,ke_a_before_j,ke_a_after_j,\
         spin_a_before_rad_s,spin_a_after_rad_s,rke_a_before_j,rke_a_after_j,\
         pb_before_x,pb_before_y,pb_after_x,pb_after_y,ke_b_before_j,ke_b_after_j,\
         spin_b_before_rad_s,spin_b_after_rad_s,rke_b_before_j,rke_b_after_j,\
         total_dp_x,total_dp_y,total_dke_j,total_drke_j\n",
    );
    for c in ledger.entries() {
        let _ = write!(
            out,
            "{},{},{},{},{}",
            c.time,
            disc_number(c.discs[0]),
            disc_number(c.discs[1]),
            c.normal.x,
            c.normal.y
        );
        let mut drke = 0.0;
        for k in 0..2 {
            let (p0, p1) = c.momentum(k);
            let (e0, e1) = c.kinetic_energy(k);
            let (r0, r1) = c.rotational_energy(k);
            let (w0, w1) = (c.spins_before[k], c.spins_after[k]);
            drke += r1 - r0;
            let _ = write!(
                out,
                ",{},{},{},{},{e0},{e1},{w0},{w1},{r0},{r1}",
                p0.x, p0.y, p1.x, p1.y
            );
        }
        let (dp, dke) = c.total_change();
        let _ = writeln!(out, ",{},{},{dke},{drke}", dp.x, dp.y);
    }
    out
}

/// The wall impacts of the ledger: the disc, the wall, its momentum,
/// kinetic energy and spin before and after, and the wall's push.
pub fn wall_hits_csv(ledger: &Ledger) -> String {
    let mut out = String::from(
        "time_s,disc,wall,normal_x,normal_y,p_before_x,p_before_y,p_after_x,p_after_y,\
         ke_before_j,ke_after_j,spin_before_rad_s,spin_after_rad_s,\
         wall_impulse_x,wall_impulse_y\n",
    );
    for w in ledger.wall_hits() {
        let n = w.normal();
        let (p0, p1) = w.momentum();
        let (e0, e1) = w.kinetic_energy();
        let j = w.wall_impulse();
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{e0},{e1},{},{},{},{}",
            w.time,
            disc_number(w.disc),
            w.wall.name(),
            n.x,
            n.y,
            p0.x,
            p0.y,
            p1.x,
            p1.y,
            w.spin_before,
            w.spin_after,
            j.x,
            j.y
        );
    }
    out
}

/// The four files, named after `stem`: totals, discs, collisions between
/// discs, impacts on walls.
pub fn files(stem: &str, samples: &[Sample], world: &World) -> [(String, String); 4] {
    [
        (format!("{stem}-totals.csv"), totals_csv(samples)),
        (format!("{stem}-discs.csv"), particles_csv(world)),
        (format!("{stem}-collisions.csv"), ledger_csv(&world.ledger)),
        (format!("{stem}-walls.csv"), wall_hits_csv(&world.ledger)),
    ]
}

/// Writes the four files into `dir` (created if needed), named after
/// `stem`; returns their paths.
pub fn export_all(
    dir: &Path,
    stem: &str,
    samples: &[Sample],
    world: &World,
) -> std::io::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir)?;
    let files = files(stem, samples, world);
    let mut written = Vec::new();
    for (name, text) in files {
        let path = dir.join(name);
        write_atomically(&path, text.as_bytes())?;
        written.push(path);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;
    use impulse::ledger::{Collision, Wall, WallHit};

    #[test]
    fn wall_rows_carry_the_walls_push() {
        let mut ledger = Ledger::default();
        ledger.keep(4);
        ledger.push(WallHit {
            time: 2.0,
            disc: 3,
            wall: Wall::Left,
            mass: 2.0,
            radius: 0.5,
            before: DVec2::new(-1.5, 0.25),
            after: DVec2::new(1.5, 0.25),
            spin_before: 0.0,
            spin_after: 0.0,
        });
        let csv = wall_hits_csv(&ledger);
        let row: Vec<&str> = csv.lines().nth(1).unwrap().split(',').collect();
        // Disc 3 of the list is the person's disc 4, as in the window.
        assert_eq!(&row[..3], ["2", "4", "left"]);
        // The push is m·(v′ − v) = 2 · (3, 0).
        assert_eq!(&row[row.len() - 2..], ["6", "0"]);
        assert_eq!(csv.lines().count(), 2);
    }

    #[test]
    fn ledger_rows_carry_the_totals_change() {
        let mut ledger = Ledger::default();
        ledger.keep(4);
        ledger.push(Collision {
            time: 1.5,
            discs: [0, 1],
            normal: DVec2::X,
            masses: [1.0, 1.0],
            before: [DVec2::new(1.0, 0.0), DVec2::new(-1.0, 0.0)],
            after: [DVec2::new(-1.0, 0.0), DVec2::new(1.0, 0.0)],
            radii: [0.5, 0.5],
            spins_before: [0.0, 0.0],
            spins_after: [0.0, 0.0],
        });
        let csv = ledger_csv(&ledger);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 2);
        let header = lines[0].split(',').count();
        let row: Vec<&str> = lines[1].split(',').collect();
        assert_eq!(row.len(), header);
        assert_eq!(&row[..3], ["1.5", "1", "2"], "discs counted from 1");
        assert_eq!(
            &row[row.len() - 3..],
            ["0", "0", "0"],
            "elastic swap: nothing changes"
        );
    }

    #[test]
    fn every_disc_is_a_row() {
        let world = impulse::presets::Gas {
            count: 7,
            ..Default::default()
        }
        .build();
        let csv = particles_csv(&world);
        assert_eq!(csv.lines().count(), 8);
        let dir = std::env::temp_dir().join(format!("impulse-export-{}", std::process::id()));
        let files = export_all(&dir, "gas", &[], &world).unwrap();
        assert_eq!(files.len(), 4);
        assert!(files.iter().all(|f| f.exists()));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

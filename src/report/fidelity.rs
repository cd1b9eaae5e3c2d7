//! The report's sections on the aircraft model itself: the flight test (the study's one
//! measurement), what was calibrated on what, both rotor angles, the propeller's predicted
//! static thrust, and how the results move with the preset's estimated values.

use super::words::{num, pct, rel};
use super::RotorResults;
use crate::diagnostics::error_line;
use crate::rotor::{Aircraft, Atmosphere, FullThrottle, Powerplant, PropellerError};
use crate::studies::paper::published::{
    TABLE1_STATIC_THRUST_N, TABLE2_ENGINE_RPM, TABLE2_ROTOR_RPM, TABLE3_TRIM,
};
use crate::studies::paper::sensitivity::{Change, Outcome, Sensitivity};
use crate::studies::paper::PAPER_TRIM_SPEED_KT;

/// What the report needs of the powerplant: its calibrated blade angle and the full-throttle
/// static equilibrium at ISA sea level.
pub(super) struct PropellerFacts {
    /// Calibrated blade angle at 0.75 R \[deg\].
    pub(super) pitch_075_deg: f64,
    /// Full throttle at rest.
    pub(super) static_point: FullThrottle,
    /// Full throttle at [`LIFTOFF_SPEED_MS`], about the takeoff's lift-off speed.
    pub(super) rolling: FullThrottle,
}

/// Airspeed of the second full-throttle point the report quotes \[m/s\] (39 kt).
pub(super) const LIFTOFF_SPEED_MS: f64 = 20.0;

impl PropellerFacts {
    /// The facts of `powerplant` in ISA sea-level air.
    pub(super) fn of(powerplant: &Powerplant) -> Result<Self, PropellerError> {
        let air = Atmosphere::isa(0.0);
        let static_point = powerplant.full_throttle(&air, 0.0, None)?;
        let rolling = powerplant.full_throttle(&air, LIFTOFF_SPEED_MS, None)?;
        Ok(Self {
            pitch_075_deg: powerplant.propeller.pitch_075.to_degrees(),
            static_point,
            rolling,
        })
    }
}

/// The paper's Table 3 value of the quantity named `name` (clean, contaminated).
fn table3(name: &str) -> [f64; 2] {
    TABLE3_TRIM
        .iter()
        .find(|q| q.name.starts_with(name))
        .map_or([f64::NAN; 2], |q| q.paper.both())
}

/// A whole number with its sign, "—" if not finite.
pub(super) fn signed(v: f64) -> String {
    if v.is_finite() {
        format!("{v:+.0}")
    } else {
        "—".to_string()
    }
}

/// The flight test, the calibration, the rotor angles and the propeller.
pub(super) fn flight_test_section(o: &mut String, ac: &Aircraft, rotor: &RotorResults) {
    let [c, d] = &rotor.trims;
    let eng = |t: &crate::rotor::TrimResult| t.engine_rpm.unwrap_or(f64::NAN);
    let (paper_rpm, paper_engine) = (table3("rotor rpm"), table3("engine rpm"));
    let test = TABLE2_ENGINE_RPM.both();
    outln!(o, "## Flight test (Table 2) — the study's one measurement");
    outln!(o);
    outln!(
        o,
        "At {PAPER_TRIM_SPEED_KT} kt the contaminated rotor needed more engine rpm, the rotor \
         rpm stayed the same. The paper's model is its Table 3."
    );
    outln!(o);
    outln!(o, "| quantity | flight test | paper model | ours |");
    outln!(o, "|---|---:|---:|---:|");
    outln!(
        o,
        "| engine rpm clean | ≈ {} | {} | {} |",
        test[0],
        paper_engine[0],
        num(eng(c), 0)
    );
    outln!(
        o,
        "| engine rpm contaminated | ≈ {} | {} | {} |",
        test[1],
        paper_engine[1],
        num(eng(d), 0)
    );
    outln!(
        o,
        "| Δ engine rpm | ≈ {:+} | {:+} | {} |",
        test[1] - test[0],
        paper_engine[1] - paper_engine[0],
        signed(eng(d) - eng(c))
    );
    outln!(
        o,
        "| rotor rpm clean / contaminated | ≈ {TABLE2_ROTOR_RPM} / ≈ {TABLE2_ROTOR_RPM} | {} / {} \
         | {} / {} |",
        paper_rpm[0],
        paper_rpm[1],
        num(c.rotor_rpm, 1),
        num(d.rotor_rpm, 1)
    );
    outln!(o);
    let p = &rotor.propeller;
    let st = &p.static_point;
    outln!(o, "What was calibrated on what:");
    outln!(o);
    outln!(
        o,
        "- **One value is calibrated:** the propeller's blade angle at 0.75 R, {:.2}°, set so \
         that the propeller gives {} N at {} kt and {} engine rpm (the paper's clean Table 3 \
         thrust at the flight test's clean rpm). The clean engine rpm above is therefore not an \
         independent prediction; it differs from {} only because our clean rotor needs {} N \
         instead of {} N.",
        p.pitch_075_deg,
        ac.propeller.calib_thrust_n,
        ac.propeller.calib_speed_kt,
        ac.propeller.calib_engine_rpm,
        ac.propeller.calib_engine_rpm,
        num(c.prop_thrust_n, 0),
        ac.propeller.calib_thrust_n,
    );
    outln!(
        o,
        "- **Predicted, not fitted:** the contaminated engine rpm and its change, the rotor rpm, \
         the rotor angles and drag, the static thrust and the takeoff. No value of the preset \
         is chosen to match Tables 2–4: each is from the paper's Table 1, manufacturer data, a \
         textbook or NACA report, or an estimate (`aircraft/mtosport.toml` says which; the \
         estimates are varied in the sensitivity table below)."
    );
    outln!(o);
    outln!(o, "### Rotor angle of attack: two angles");
    outln!(o);
    let alpha_paper = table3("rotor AoA");
    outln!(
        o,
        "The paper's α_R is the angle of the resultant rotor force behind the normal to the \
         flight path: its eq. 5 writes the rotor drag as G·α_R, and its Table 3 has \
         atan(478/4414) = 6.2° and atan(624/4414) = 8.1°. Ours of that kind is \
         atan(D_R/L_R) and is what Table 3 below compares. The tip-path-plane angle (the \
         disc's attitude, what a vane would show) is smaller by about H/T, the in-plane force \
         the blades' profile drag adds."
    );
    outln!(o);
    outln!(
        o,
        "| | paper α_R | ours atan(D_R/L_R) | ours tip-path plane | ours hub |"
    );
    outln!(o, "|---|---:|---:|---:|---:|");
    for (label, t, paper) in [
        ("clean rotor", c, alpha_paper[0]),
        ("contaminated rotor", d, alpha_paper[1]),
    ] {
        outln!(
            o,
            "| {label} | {paper} | {} | {} | {} |",
            num(t.rotor_aoa_drag_equivalent_deg, 2),
            num(t.rotor_aoa_deg, 2),
            num(t.hub_aoa_deg, 2)
        );
    }
    outln!(o);
    outln!(o, "### Rotor model choices");
    outln!(o);
    outln!(
        o,
        "- **Tip loss `{}`:** with `prandtl`, Prandtl's factor from each strip's inflow angle \
         against its rotational speed Ωr at every azimuth (Prandtl 1919; Leishman, ch. 3). In \
         autorotation the net inflow is small and the wake is swept aft, so it removes little \
         lift (equivalent B ≈ 0.98–0.99 here); Gessow–Myers' hover relation (B ≈ 0.96) would \
         add a lift-free, draggy tip strip that drives the rotor faster. The other models are \
         in the sensitivity table.",
        Change::TipLoss(ac.rotor.tip_loss).value()
    );
    outln!(
        o,
        "- **Yawed flow `{}`:** with `radial_drag`, the profile drag acts along the whole \
         relative wind including the radial component, the textbook forward-flight profile \
         power (σc_d0/8)(1 + Kμ²) with K ≈ 4.6 instead of 3 (Leishman, ch. 5; Johnson, \
         *Helicopter Theory*, ch. 5); `none` drops it (sensitivity table).",
        Change::YawedFlow(ac.rotor.yawed_flow).value()
    );
    outln!(
        o,
        "- **Inflow `{}`:** with `drees`, Glauert's mean induced velocity with Drees' linear \
         fore-aft and lateral gradients (Leishman, ch. 10); on the PCA-2's flight test (NACA \
         Report 487, section \"The rotor model on a second rotor\") it gives the lateral \
         flapping that uniform inflow misses. `glauert` (uniform) is in the sensitivity table.",
        Change::Inflow(ac.rotor.inflow).value()
    );
    outln!(o);
    outln!(o, "### Propeller");
    outln!(o);
    outln!(
        o,
        "A blade-element–momentum propeller (Prandtl tip loss, swirl) of the preset's blade \
         (NACA Report 594 propeller D blade form, 3 blades, 1.72 m) with the blade's own \
         sections: our tables of the Clark Y family at its thickness ratios (8 % at the tip to \
         44 % at the shank, each annulus interpolating in t/c), driven by the Rotax 912 ULS \
         full-throttle torque curve through the 2.43 gear; its chart is checked against NACA \
         Report 594 in `tests/rotor_propeller.rs`. Full-throttle static thrust, predicted: \
         **{} N** at {} engine rpm{}, against ≈ {TABLE1_STATIC_THRUST_N} N in the paper's \
         Table 1 ({}). There {:.0} % of its annuli are stalled beyond their table's usable α \
         range (past stall, where the tables' points are in massive separation; their data from the tables' 360° extension: Viterna & Corrigan to 90°, then a \
         flat plate of broadside drag 2.0, Hoerner) and {:.0} % lean on supercritical table \
         points (locally supersonic, outside the section method's validity): the static point \
         is where the propeller model is least sure. A two-dimensional polar without rotational \
         stall delay under-predicts a propeller's static power (NACA 594 at 30°: −43 %, at 45°: \
         −31 %), so the engine may turn too fast and the static thrust be over-predicted. The \
         same stall modelling makes the power coefficient rise with the advance ratio at low \
         J, where NACA 594 shows it flat or falling: at {LIFTOFF_SPEED_MS} m/s the \
         full-throttle rpm has fallen to {} and the thrust to {} N ({}), a faster thrust lapse \
         than a real fixed-pitch propeller's, which lengthens the takeoff (Table 4).",
        num(st.propeller.thrust, 0),
        num(st.engine_rpm, 0),
        if st.rpm_limited {
            " (held at the maximum rpm)"
        } else {
            ""
        },
        pct(rel(TABLE1_STATIC_THRUST_N, st.propeller.thrust)),
        100.0 * st.propeller.post_stall_fraction,
        100.0 * st.propeller.supercritical_fraction,
        num(p.rolling.engine_rpm, 0),
        num(p.rolling.propeller.thrust, 0),
        pct(rel(st.propeller.thrust, p.rolling.propeller.thrust)),
    );
    outln!(o);
}

/// One result of the sensitivity table: its name, how to read it from an outcome, decimals.
type Quantity = (&'static str, fn(&Outcome) -> f64, usize);

/// The sensitivity table and what it says.
pub(super) fn sensitivity_section(o: &mut String, s: &Sensitivity) {
    outln!(o, "## Sensitivity to the estimated values");
    outln!(o);
    outln!(
        o,
        "Each estimate of `aircraft/mtosport.toml`, and the trim mass (the flight test's is not \
         published), set to the ends of its plausible range one at a time; everything else as \
         in the preset. Clean rotor rpm and the contamination changes of engine rpm and \
         propeller thrust at {PAPER_TRIM_SPEED_KT} kt, and the clean takeoff distances. The \
         trim mass changes the trims only (the paper's takeoff is at 450 kg)."
    );
    outln!(o);
    outln!(
        o,
        "| estimate | preset | tried | range | clean n_R [rpm] | Δ engine rpm | ΔF_prop [%] | \
         s_TO [m] | s_15 [m] |"
    );
    outln!(o, "|---|---|---|---|---:|---:|---:|---:|---:|");
    let cells = |x: &Outcome| {
        format!(
            "{} | {} | {} | {} | {}",
            num(x.clean_rotor_rpm, 1),
            num(x.delta_engine_rpm, 0),
            num(x.delta_prop_thrust_percent, 1),
            num(x.takeoff_roll_m, 1),
            num(x.distance_15m_m, 1)
        )
    };
    outln!(o, "| **preset values** | | | | {} |", cells(&s.baseline));
    let mut failed = Vec::new();
    for row in &s.rows {
        let e = row.estimate;
        match &row.outcome {
            Ok(x) => outln!(
                o,
                "| {} | {} | {} | {} | {} |",
                e.name,
                e.preset,
                row.change.value(),
                e.range,
                cells(x)
            ),
            Err(err) => {
                outln!(
                    o,
                    "| {} | {} | {} | {} | — | — | — | — | — |",
                    e.name,
                    e.preset,
                    row.change.value(),
                    e.range
                );
                failed.push(format!(
                    "{} = {}: {}",
                    e.name,
                    row.change.value(),
                    error_line(err)
                ));
            }
        }
    }
    outln!(o);
    // The estimate that moves each result most, and the spread over all rows.
    let base = &s.baseline;
    let quantities: [Quantity; 5] = [
        ("clean rotor rpm", |x| x.clean_rotor_rpm, 1),
        ("Δ engine rpm", |x| x.delta_engine_rpm, 0),
        ("ΔF_prop [%]", |x| x.delta_prop_thrust_percent, 1),
        ("s_TO [m]", |x| x.takeoff_roll_m, 1),
        ("s_15 [m]", |x| x.distance_15m_m, 1),
    ];
    for (name, of, decimals) in quantities {
        let rows: Vec<(&str, String, f64)> = s
            .rows
            .iter()
            .filter_map(|r| {
                let x = r.outcome.as_ref().ok()?;
                Some((r.estimate.name, r.change.value(), of(x)))
            })
            .filter(|r| r.2.is_finite())
            .collect();
        let lo = rows.iter().map(|r| r.2).fold(of(base), f64::min);
        let hi = rows.iter().map(|r| r.2).fold(of(base), f64::max);
        if let Some(worst) = rows
            .iter()
            .max_by(|a, b| (a.2 - of(base)).abs().total_cmp(&(b.2 - of(base)).abs()))
        {
            outln!(
                o,
                "- **{name}:** {} with the preset, {} … {} over the table; moved most by {} = {} \
                 ({}).",
                num(of(base), decimals),
                num(lo, decimals),
                num(hi, decimals),
                worst.0,
                worst.1,
                num(worst.2, decimals)
            );
        }
    }
    for f in failed {
        outln!(o, "- Not computed: {f}.");
    }
    outln!(o);
}

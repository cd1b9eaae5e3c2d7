//! The command-line text of the rotor results (`gyro`'s stdout): the trim, takeoff and
//! tunnel-autorotation summaries, the speed-sweep table and the paper comparison (Tables 3 and
//! 4, text and JSON).
//! Each function appends to a text buffer the tool prints.

use crate::rotor::{Autorotation, TakeoffResult, TrimResult};
use crate::studies::paper::published::{
    change_percent as rel, compare as paired, Comparison, TABLE3_TRIM, TABLE4_TAKEOFF,
};
use crate::studies::paper::PaperRun;
use serde::Serialize;

/// Engine rpm as printed, or `above max` when the engine cannot reach the thrust.
fn engine_text(e: Option<f64>) -> String {
    e.map_or_else(|| "above max".to_string(), |v| format!("{v:.0}"))
}

/// The trim summary.
pub fn trim(buf: &mut String, t: &TrimResult) {
    outln!(buf, "trim at {:.1} kt", t.airspeed_kt);
    outln!(buf, "  rotor rpm n_R          {:8.1}", t.rotor_rpm);
    outln!(
        buf,
        "  rotor AoA alpha_R [deg]{:8.2}   (atan D_R/L_R; tip-path plane {:.2}, hub {:.2})",
        t.rotor_aoa_drag_equivalent_deg,
        t.rotor_aoa_deg,
        t.hub_aoa_deg
    );
    outln!(
        buf,
        "  engine rpm             {:>8}",
        engine_text(t.engine_rpm)
    );
    outln!(buf, "  rotor drag D_R [N]     {:8.1}", t.rotor_drag_n);
    outln!(buf, "  parasitic D_P [N]      {:8.1}", t.parasitic_drag_n);
    if let Some(w) = &t.wing {
        outln!(
            buf,
            "  wing drag D_W [N]      {:8.1}   (lift {:.1} N, C_L {:.3}; the rotor lifts {:.1} %)",
            w.drag_n,
            w.lift_n,
            w.lift_coefficient,
            100.0 * t.rotor_lift_share()
        );
    }
    outln!(buf, "  prop thrust F_prop [N] {:8.1}", t.prop_thrust_n);
    outln!(buf, "  L/D                    {:8.2}", t.lift_to_drag);
    outln!(buf, "  power required [kW]    {:8.1}", t.power_required_kw);
    outln!(
        buf,
        "  static thrust [N]      {:8.1}   (annuli beyond the computed alpha range {:.0} %, \
         supercritical {:.0} %)",
        t.static_thrust_n,
        100.0 * t.static_thrust_post_stall_fraction,
        100.0 * t.static_thrust_supercritical_fraction
    );
    outln!(
        buf,
        "  flapping b1c, b1s [deg]{:8.2} {:.2}",
        t.beta1c_deg,
        t.beta1s_deg
    );
}

/// The summary of the autorotating rotor in the tunnel.
pub fn autorotation(buf: &mut String, a: &Autorotation) {
    outln!(
        buf,
        "autorotation at alpha {} deg, V {} m/s",
        crate::limits::short_number(a.alpha_deg),
        crate::limits::short_number(a.speed_m_s)
    );
    outln!(buf, "  rotor rpm                {:9.2}", a.rotor_rpm);
    outln!(buf, "  tip-speed ratio mu       {:9.4}", a.mu);
    outln!(
        buf,
        "  lift coefficient C_L     {:9.4}   (on q pi R^2)",
        a.cl
    );
    outln!(buf, "  drag coefficient C_D     {:9.5}", a.cd);
    outln!(buf, "  L/D                      {:9.3}", a.lift_to_drag);
    outln!(
        buf,
        "  thrust coefficient C_T   {:9.5}",
        a.thrust_coefficient
    );
    outln!(buf, "  inflow ratio lambda      {:9.5}", a.inflow_ratio);
    outln!(
        buf,
        "  coning a0, flapping a1, b1 [deg] {:.2} {:.2} {:.2}   (NACA signs)",
        a.coning_deg,
        a.a1_deg,
        a.b1_deg
    );
    outln!(
        buf,
        "  reverse flow             {:9.1} %",
        100.0 * a.reverse_flow_fraction
    );
}

/// The takeoff summary.
pub fn takeoff(buf: &mut String, t: &TakeoffResult) {
    outln!(buf, "takeoff");
    outln!(buf, "  takeoff roll s_TO [m]      {:7.1}", t.takeoff_roll_m);
    outln!(buf, "  distance to 15 m s_15 [m]  {:7.1}", t.distance_15m_m);
    outln!(
        buf,
        "  max flapping beta_max [deg]{:7.2}{}",
        t.max_flapping_deg,
        if t.flap_stops_reached {
            "  (on the stops)"
        } else {
            ""
        }
    );
    outln!(
        buf,
        "  lift-off speed [kt]        {:7.1}  at {:.1} s, rotor {:.0} rpm",
        t.liftoff_speed_kt,
        t.liftoff_time_s,
        t.liftoff_rotor_rpm
    );
    outln!(
        buf,
        "  speed at 15 m [kt]         {:7.1}  at {:.1} s",
        t.screen_speed_kt,
        t.screen_time_s
    );
}

/// The speed-sweep table, one row per trimmed speed.
pub fn sweep(buf: &mut String, trims: &[TrimResult]) {
    outln!(
        buf,
        "{:>7} {:>7} {:>7} {:>8} {:>8} {:>8} {:>8} {:>6} {:>7}",
        "V[kt]",
        "n_R",
        "a_R",
        "engine",
        "D_R[N]",
        "D_P[N]",
        "F_P[N]",
        "L/D",
        "P[kW]"
    );
    for r in trims {
        outln!(
            buf,
            "{:7.1} {:7.1} {:7.2} {:>8} {:8.1} {:8.1} {:8.1} {:6.2} {:7.1}",
            r.airspeed_kt,
            r.rotor_rpm,
            r.rotor_aoa_deg,
            engine_text(r.engine_rpm),
            r.rotor_drag_n,
            r.parasitic_drag_n,
            r.prop_thrust_n,
            r.lift_to_drag,
            r.power_required_kw
        );
    }
}

/// `value` as pretty JSON with a final newline (the `--json` output of every command).
pub fn json<T: serde::Serialize + ?Sized>(value: &T) -> Result<String, serde_json::Error> {
    Ok(serde_json::to_string_pretty(value)? + "\n")
}

/// The blade α(ψ) curve as CSV (`psi_deg,alpha_deg`), ψ to 0.1°, α to 0.001°.
pub fn blade_alpha(buf: &mut String, curve: &[(f64, f64)]) {
    outln!(buf, "psi_deg,alpha_deg");
    for (psi, a) in curve {
        outln!(buf, "{psi:.1},{a:.3}");
    }
}

/// Tables 3 and 4 of the paper beside ours.
fn tables([clean, dirty]: &[PaperRun; 2]) -> [Vec<Comparison>; 2] {
    [
        paired(&TABLE3_TRIM, &clean.trim, &dirty.trim),
        paired(&TABLE4_TAKEOFF, &clean.takeoff, &dirty.takeoff),
    ]
}

/// Tables 3 and 4 as text: paper clean, contaminated and change beside ours.
pub fn compare(buf: &mut String, runs: &[PaperRun; 2]) {
    let [trim, takeoff] = tables(runs);
    let table = |buf: &mut String, title: &str, rows: &[Comparison]| {
        outln!(buf, "{title}");
        outln!(buf, "                                   paper     paper    paper |      ours      ours     ours");
        outln!(buf, "  quantity                         clean   contam.   change |     clean   contam.   change");
        for r in rows {
            let (q, pc, pd) = (r.name, r.paper.clean, r.paper.contaminated);
            let (oc, od) = (r.ours.clean, r.ours.contaminated);
            outln!(
                buf,
                "  {q:<28} {pc:>9.1} {pd:>9.1} {:>+7.1}% | {oc:>9.1} {od:>9.1} {:>+7.1}%",
                rel(pc, pd),
                rel(oc, od)
            );
        }
    };
    table(buf, "Table 3 — trim at 60 kt, ISA sea level", &trim);
    outln!(buf);
    table(buf, "Table 4 — takeoff, ISA sea level, no wind", &takeoff);
}

/// One row of the JSON comparison.
#[derive(Serialize)]
struct Row {
    quantity: &'static str,
    paper_clean: f64,
    paper_contaminated: f64,
    ours_clean: f64,
    ours_contaminated: f64,
}

/// Tables 3 and 4 as JSON: `{"trim": [rows], "takeoff": [rows]}`.
pub fn compare_json(buf: &mut String, runs: &[PaperRun; 2]) -> Result<(), serde_json::Error> {
    buf.push_str(&json(&compare_rows(runs))?);
    Ok(())
}

/// Tables 3 and 4 as a JSON value: `{"trim": [rows], "takeoff": [rows]}`, each row
/// `quantity`, `paper_clean`, `paper_contaminated`, `ours_clean`, `ours_contaminated`.
pub fn compare_rows(runs: &[PaperRun; 2]) -> serde_json::Value {
    let rows = |table: &[Comparison]| -> Vec<Row> {
        table
            .iter()
            .map(|r| Row {
                quantity: r.name,
                paper_clean: r.paper.clean,
                paper_contaminated: r.paper.contaminated,
                ours_clean: r.ours.clean,
                ours_contaminated: r.ours.contaminated,
            })
            .collect()
    };
    let [trim, takeoff] = tables(runs);
    serde_json::json!({ "trim": rows(&trim), "takeoff": rows(&takeoff) })
}

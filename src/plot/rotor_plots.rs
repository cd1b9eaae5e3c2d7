//! Rotor results: blade local angle of attack vs azimuth, takeoff time histories and the
//! power-required curve of a speed sweep, several cases overlaid (clean vs contaminated).
//!
//! The `*_figure` functions draw plain slices; [`alpha_figure`], [`takeoff_plot`] and
//! [`power_plot`] take the rotor model's results and give each case its study style
//! ([`case_style`]).

use super::figure::{Figure, Marker, Panel, Series, Style};
use crate::rotor::{TakeoffResult, TrimResult, KT_TO_MS};

/// Palette index used for case-independent reference lines (grey).
const REFERENCE_COLOR: usize = 7;

/// Blade local α over one revolution at one radial station.
#[derive(Clone, Copy, Debug, Default)]
pub struct AzimuthCase<'a> {
    /// Legend label, e.g. `"clean"`.
    pub label: &'a str,
    /// Colour and line kind.
    pub style: Style,
    /// Azimuth ψ \[deg\], ψ = 0 with the blade pointing to the rear, increasing in the direction
    /// of rotation (ψ = 90° advancing, 270° retreating).
    pub psi_deg: &'a [f64],
    /// Local angle of attack \[deg\].
    pub alpha_deg: &'a [f64],
}

/// Local α vs azimuth ψ ∈ \[0°, 360°\] (the paper's Fig. 10), the maximum of each case marked
/// and labelled with its value and azimuth.
pub fn alpha_azimuth_figure(cases: &[AzimuthCase], title: &str) -> Figure {
    let mut panel = Panel::new("", "azimuth ψ [deg] (0 = rear)", "local α [deg]")
        .with_x_range(0.0, 360.0)
        .with_x_tick_step(45.0);
    for c in cases {
        panel.series.push(Series::from_slices(
            c.label,
            c.psi_deg,
            c.alpha_deg,
            c.style,
        ));
        let max = c
            .psi_deg
            .iter()
            .zip(c.alpha_deg)
            .filter(|(p, a)| p.is_finite() && a.is_finite())
            .max_by(|a, b| a.1.total_cmp(b.1));
        if let Some((&psi, &alpha)) = max {
            panel.markers.push(Marker::point(
                psi,
                alpha,
                format!("max {}: {alpha:.1}° at ψ = {psi:.0}°", c.label),
                c.style.color,
            ));
        }
    }
    Figure::new(title).with_panel(panel)
}

/// Time histories of one takeoff simulation.
#[derive(Clone, Copy, Debug, Default)]
pub struct TakeoffCase<'a> {
    /// Legend label, e.g. `"contaminated"`.
    pub label: &'a str,
    /// Colour and line kind.
    pub style: Style,
    /// Time \[s\].
    pub t: &'a [f64],
    /// Speed \[kt\].
    pub speed_kt: &'a [f64],
    /// Height above ground \[m\].
    pub height_m: &'a [f64],
    /// Rotor speed \[rpm\].
    pub rotor_rpm: &'a [f64],
    /// Blade flapping angle \[deg\].
    pub flapping_deg: &'a [f64],
    /// Lift-off time \[s\], marked by a vertical line.
    pub liftoff_t: Option<f64>,
}

/// Takeoff time histories (the paper's Fig. 11), 2 × 2: speed, height (15 m obstacle
/// marked), rotor rpm and flapping vs time, lift-off instants marked.
pub fn takeoff_figure(cases: &[TakeoffCase], title: &str) -> Figure {
    let mut speed = Panel::new("Speed", "time [s]", "speed [kt]");
    let mut height = Panel::new("Height", "time [s]", "height [m]").with_marker(Marker::hline(
        15.0,
        "15 m obstacle",
        REFERENCE_COLOR,
    ));
    let mut rpm = Panel::new("Rotor speed", "time [s]", "rotor speed [rpm]");
    let mut flap = Panel::new("Flapping", "time [s]", "flapping β [deg]");
    for c in cases {
        for (panel, y) in [
            (&mut speed, c.speed_kt),
            (&mut height, c.height_m),
            (&mut rpm, c.rotor_rpm),
            (&mut flap, c.flapping_deg),
        ] {
            panel
                .series
                .push(Series::from_slices(c.label, c.t, y, c.style));
            if let Some(t) = c.liftoff_t {
                panel.markers.push(Marker::vline(
                    t,
                    format!("lift-off, {} (t = {t:.1} s)", c.label),
                    c.style.color,
                ));
            }
        }
    }
    Figure::new(title)
        .with_panel(speed)
        .with_panel(height)
        .with_panel(rpm)
        .with_panel(flap)
}

/// A speed sweep of trimmed level flight.
#[derive(Clone, Copy, Debug, Default)]
pub struct PowerCase<'a> {
    /// Legend label.
    pub label: &'a str,
    /// Colour and line kind.
    pub style: Style,
    /// Airspeed \[kt\].
    pub speed_kt: &'a [f64],
    /// Power required \[kW\] (empty if not computed).
    pub power_kw: &'a [f64],
    /// Propeller thrust required \[N\] (empty if not computed).
    pub thrust_n: &'a [f64],
}

/// Power-required curves: power \[kW\] and propeller thrust \[N\] vs airspeed, side by side.
pub fn power_required_figure(cases: &[PowerCase], title: &str) -> Figure {
    let mut power = Panel::new("Power required", "airspeed [kt]", "power [kW]");
    let mut thrust = Panel::new("Thrust required", "airspeed [kt]", "propeller thrust [N]");
    for c in cases {
        for (panel, y) in [(&mut power, c.power_kw), (&mut thrust, c.thrust_n)] {
            if !y.is_empty() {
                panel.series.push(Series::from_slices(
                    c.label,
                    c.speed_kt,
                    y,
                    c.style.with_points(),
                ));
            }
        }
    }
    Figure::new(title).with_panel(power).with_panel(thrust)
}

/// Line style of case `i` of the study: clean solid blue, contaminated dashed red (distinct in
/// grey print).
pub fn case_style(i: usize) -> Style {
    if i == 0 {
        Style::solid(0)
    } else {
        Style::dashed(1)
    }
}

/// Blade α vs azimuth for the cases given as (label, (ψ \[deg\], α \[deg\]) samples over one
/// revolution from ψ = 0); each curve is closed at ψ = 360° with its ψ = 0 value.
pub fn alpha_figure(curves: &[(&str, &[(f64, f64)])], title: &str) -> Figure {
    let closed: Vec<(Vec<f64>, Vec<f64>)> = curves
        .iter()
        .map(|(_, samples)| {
            let mut psi: Vec<f64> = samples.iter().map(|s| s.0).collect();
            let mut alpha: Vec<f64> = samples.iter().map(|s| s.1).collect();
            if let Some(&(psi0, a0)) = samples.first() {
                psi.push(psi0 + 360.0);
                alpha.push(a0);
            }
            (psi, alpha)
        })
        .collect();
    let cases: Vec<AzimuthCase> = curves
        .iter()
        .zip(&closed)
        .enumerate()
        .map(|(i, ((label, _), (psi, alpha)))| AzimuthCase {
            label,
            style: case_style(i),
            psi_deg: psi,
            alpha_deg: alpha,
        })
        .collect();
    alpha_azimuth_figure(&cases, title)
}

/// Takeoff time histories of the cases given as (label, result): speed \[kt\], height \[m\],
/// rotor rpm and flapping \[deg\] vs time, lift-off marked.
pub fn takeoff_plot(runs: &[(&str, &TakeoffResult)], title: &str) -> Figure {
    let columns: Vec<[Vec<f64>; 5]> = runs
        .iter()
        .map(|(_, r)| {
            let h = &r.history;
            [
                h.iter().map(|s| s.t).collect(),
                h.iter().map(|s| s.v / KT_TO_MS).collect(),
                h.iter().map(|s| s.h).collect(),
                h.iter().map(|s| s.rotor_rpm).collect(),
                h.iter().map(|s| s.beta_deg).collect(),
            ]
        })
        .collect();
    let cases: Vec<TakeoffCase> = runs
        .iter()
        .zip(&columns)
        .enumerate()
        .map(|(i, ((label, r), [t, v, h, rpm, beta]))| TakeoffCase {
            label,
            style: case_style(i),
            t,
            speed_kt: v,
            height_m: h,
            rotor_rpm: rpm,
            flapping_deg: beta,
            liftoff_t: Some(r.liftoff_time_s),
        })
        .collect();
    takeoff_figure(&cases, title)
}

/// Power and propeller thrust required vs airspeed for the cases given as (label, trims of a
/// speed sweep in increasing speed).
pub fn power_plot(sweeps: &[(&str, &[TrimResult])], title: &str) -> Figure {
    let columns: Vec<[Vec<f64>; 3]> = sweeps
        .iter()
        .map(|(_, trims)| {
            [
                trims.iter().map(|t| t.airspeed_kt).collect(),
                trims.iter().map(|t| t.power_required_kw).collect(),
                trims.iter().map(|t| t.prop_thrust_n).collect(),
            ]
        })
        .collect();
    let cases: Vec<PowerCase> = sweeps
        .iter()
        .zip(&columns)
        .enumerate()
        .map(|(i, ((label, _), [v, p, f]))| PowerCase {
            label,
            style: case_style(i),
            speed_kt: v,
            power_kw: p,
            thrust_n: f,
        })
        .collect();
    power_required_figure(&cases, title)
}

//! Rotor figures (blade α against azimuth, takeoff time histories, power required) rendered
//! to SVG and PNG. The inputs are synthetic but shaped like the study's results (no rotor
//! model is needed to test plots); each figure is checked as in `plot_figures.rs`.

use std::f64::consts::PI;

use polargen::plot::rotor_plots::{
    alpha_azimuth_figure, power_required_figure, takeoff_figure, AzimuthCase, PowerCase,
    TakeoffCase,
};
use polargen::plot::Style;

mod plot_support;
use plot_support::{render_and_check, svg_texts};

/// Synthetic blade local α at r/R = 0.9 (test input only): pitch θ plus the inflow angle
/// atan(λ / (r + μ sin ψ)) of a blade element in forward flight, ψ = 0 at the
/// rear, so the tangential speed is lowest and α highest on the retreating side (ψ = 270°).
fn synthetic_alpha(theta_deg: f64, lambda: f64, mu: f64) -> (Vec<f64>, Vec<f64>) {
    let r = 0.9;
    (0..=72)
        .map(|k| {
            let psi = 5.0 * k as f64;
            let s = (psi * PI / 180.0).sin();
            let phi = lambda / (r + mu * s);
            (psi, theta_deg + phi.atan().to_degrees())
        })
        .unzip()
}

#[test]
fn rotor_alpha_vs_azimuth() {
    let (psi, a_clean) = synthetic_alpha(2.5, 0.03, 0.22);
    let (_, a_cont) = synthetic_alpha(2.5, 0.045, 0.22);
    let cases = [
        AzimuthCase {
            label: "clean",
            style: Style::solid(0),
            psi_deg: &psi,
            alpha_deg: &a_clean,
        },
        AzimuthCase {
            label: "contaminated",
            style: Style::dashed(1),
            psi_deg: &psi,
            alpha_deg: &a_cont,
        },
    ];
    let fig = alpha_azimuth_figure(&cases, "Blade local α at r = 0.9 R, 60 kt");
    // The maximum must be on the retreating side (ψ = 270°) for μ > 0.
    let max_label = &fig.panels[0].markers[0].label;
    assert!(max_label.contains("ψ = 270°"), "{max_label}");
    let svg = render_and_check(
        &fig,
        "alpha_azimuth",
        &["azimuth ψ [deg] (0 = rear)", "local α [deg]", "max clean"],
        &[0, 1],
    );
    // Azimuth ticks every 45°.
    let texts: Vec<String> = svg_texts(&svg).into_iter().map(|(_, t)| t).collect();
    for tick in ["0", "90", "180", "270", "360"] {
        assert!(
            texts.iter().any(|t| t == tick),
            "azimuth tick {tick} missing"
        );
    }
}

#[test]
fn rotor_takeoff_and_power_required() {
    let t: Vec<f64> = (0..=150).map(|k| 0.1 * k as f64).collect();
    let history = |liftoff: f64, scale: f64| {
        let speed: Vec<f64> = t
            .iter()
            .map(|&t| 50.0 * (1.0 - (-t / (6.0 * scale)).exp()))
            .collect();
        let height: Vec<f64> = t
            .iter()
            .map(|&t| (2.0 * (t - liftoff) / scale).max(0.0).powf(1.5))
            .collect();
        let rpm: Vec<f64> = t
            .iter()
            .map(|&t| 350.0 - 150.0 * (-t / (4.0 * scale)).exp())
            .collect();
        let flap: Vec<f64> = t
            .iter()
            .map(|&t| 4.0 * scale * (t / 3.0).min(1.0) * (-t / 12.0).exp())
            .collect();
        (speed, height, rpm, flap)
    };
    let (s1, h1, r1, f1) = history(8.0, 1.0);
    let (s2, h2, r2, f2) = history(9.5, 1.15);
    let cases = [
        TakeoffCase {
            label: "clean",
            style: Style::solid(0),
            t: &t,
            speed_kt: &s1,
            height_m: &h1,
            rotor_rpm: &r1,
            flapping_deg: &f1,
            liftoff_t: Some(8.0),
        },
        TakeoffCase {
            label: "contaminated",
            style: Style::dashed(1),
            t: &t,
            speed_kt: &s2,
            height_m: &h2,
            rotor_rpm: &r2,
            flapping_deg: &f2,
            liftoff_t: Some(9.5),
        },
    ];
    render_and_check(
        &takeoff_figure(&cases, "Takeoff, m = 450 kg, standard atmosphere"),
        "takeoff",
        &[
            "speed [kt]",
            "height [m]",
            "rotor speed [rpm]",
            "flapping β [deg]",
            "15 m obstacle",
            "lift-off, clean (t = 8.0 s)",
        ],
        &[0, 1],
    );

    let v: Vec<f64> = (0..=12).map(|k| 30.0 + 5.0 * k as f64).collect();
    let curve = |k: f64| -> (Vec<f64>, Vec<f64>) {
        v.iter()
            .map(|&v| {
                let ms = v * 0.514444;
                let thrust = k
                    * (0.5 * 1.225 * ms * ms
                        + 4414.0 * 4414.0 / (0.5 * 1.225 * ms * ms * 55.4 * 4.0));
                (thrust * ms / 1000.0, thrust)
            })
            .unzip()
    };
    let (p1, t1) = curve(1.0);
    let (p2, t2) = curve(1.14);
    let power = [
        PowerCase {
            label: "clean",
            style: Style::solid(0),
            speed_kt: &v,
            power_kw: &p1,
            thrust_n: &t1,
        },
        PowerCase {
            label: "contaminated",
            style: Style::dashed(1),
            speed_kt: &v,
            power_kw: &p2,
            thrust_n: &t2,
        },
    ];
    render_and_check(
        &power_required_figure(&power, "Power required in level flight"),
        "power",
        &["airspeed [kt]", "power [kW]", "propeller thrust [N]"],
        &[0, 1],
    );
}

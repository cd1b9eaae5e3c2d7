//! The panel method against the exact potential flow about a Kármán–Trefftz airfoil
//! (conformal map of a circle, e.g. Milne-Thomson, "Theoretical Aerodynamics", §7.5; Katz &
//! Plotkin, "Low-Speed Aerodynamics", §6.8): Cp error falls as panels are added and Cl
//! converges to the Kutta–Joukowski value.

use polargen::geometry::Airfoil;
use polargen::inviscid::PanelSystem;

/// Minimal complex number for the conformal map.
#[derive(Clone, Copy, Debug)]
struct C(f64, f64);

impl C {
    fn add(self, o: C) -> C {
        C(self.0 + o.0, self.1 + o.1)
    }
    fn sub(self, o: C) -> C {
        C(self.0 - o.0, self.1 - o.1)
    }
    fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    fn div(self, o: C) -> C {
        let d = o.0 * o.0 + o.1 * o.1;
        C(
            (self.0 * o.0 + self.1 * o.1) / d,
            (self.1 * o.0 - self.0 * o.1) / d,
        )
    }
    fn scale(self, k: f64) -> C {
        C(self.0 * k, self.1 * k)
    }
    fn abs(self) -> f64 {
        self.0.hypot(self.1)
    }
    /// Principal power z^p.
    fn powf(self, p: f64) -> C {
        let (r, t) = (self.abs(), self.1.atan2(self.0));
        let rp = r.powf(p);
        C(rp * (p * t).cos(), rp * (p * t).sin())
    }
    fn expi(t: f64) -> C {
        C(t.cos(), t.sin())
    }
}

/// Kármán–Trefftz airfoil: circle centre (−mx, my) through ζ = a = 1, TE angle `tau`.
struct KarmanTrefftz {
    centre: C,
    radius: f64,
    beta: f64,
    n: f64,
}

impl KarmanTrefftz {
    fn new(mx: f64, my: f64, tau_deg: f64) -> Self {
        let centre = C(-mx, my);
        let d = C(1.0, 0.0).sub(centre);
        Self {
            centre,
            radius: d.abs(),
            beta: my.atan2(1.0 + mx),
            n: 2.0 - tau_deg.to_radians() / std::f64::consts::PI,
        }
    }

    /// Circle point at angle θ.
    fn zeta(&self, theta: f64) -> C {
        self.centre.add(C::expi(theta).scale(self.radius))
    }

    /// z(ζ) = n·a·(1 + r)/(1 − r), r = ((ζ − a)/(ζ + a))^n, a = 1.
    fn map(&self, zeta: C) -> C {
        let one = C(1.0, 0.0);
        let r = zeta.sub(one).div(zeta.add(one)).powf(self.n);
        one.add(r).div(one.sub(r)).scale(self.n)
    }

    /// dz/dζ = 4n²a²·r / ((1 − r)²(ζ² − a²)).
    fn dmap(&self, zeta: C) -> C {
        let one = C(1.0, 0.0);
        let r = zeta.sub(one).div(zeta.add(one)).powf(self.n);
        let om = one.sub(r);
        r.scale(4.0 * self.n * self.n)
            .div(om.mul(om).mul(zeta.mul(zeta).sub(one)))
    }

    /// Circulation satisfying the Kutta condition at ζ = a for unit freestream.
    fn circulation(&self, alpha: f64) -> f64 {
        4.0 * std::f64::consts::PI * self.radius * (alpha + self.beta).sin()
    }

    /// Exact surface speed |dW/dz| at circle angle θ.
    fn speed(&self, theta: f64, alpha: f64) -> f64 {
        let zp = C::expi(theta).scale(self.radius);
        let gam = self.circulation(alpha);
        let w = C::expi(-alpha)
            .sub(
                C::expi(alpha)
                    .scale(self.radius * self.radius)
                    .div(zp.mul(zp)),
            )
            .add(C(0.0, gam / (2.0 * std::f64::consts::PI)).div(zp));
        w.abs() / self.dmap(self.zeta(theta)).abs()
    }

    /// Chord: largest distance from the TE to a contour point (fine sampling).
    fn chord(&self) -> f64 {
        let te = self.map(self.zeta(-self.beta));
        (1..20000)
            .map(|k| {
                let t = -self.beta + 2.0 * std::f64::consts::PI * k as f64 / 20000.0;
                self.map(self.zeta(t)).sub(te).abs()
            })
            .fold(0.0, f64::max)
    }

    /// N panels, nodes at equal circle angles from the TE (XFOIL order, first = last node),
    /// scaled to unit chord with the TE at (1, 0); also returns the node angles.
    fn nodes(&self, panels: usize) -> (Airfoil, Vec<f64>) {
        let chord = self.chord();
        let te = self.map(self.zeta(-self.beta));
        let mut x = Vec::new();
        let mut y = Vec::new();
        let mut th = Vec::new();
        for k in 0..=panels {
            let t = -self.beta + 2.0 * std::f64::consts::PI * k as f64 / panels as f64;
            let z = if k == 0 || k == panels {
                te
            } else {
                self.map(self.zeta(t))
            };
            x.push((z.0 - te.0) / chord + 1.0);
            y.push((z.1 - te.1) / chord);
            th.push(t);
        }
        let foil = Airfoil {
            name: "Karman-Trefftz".into(),
            x,
            y,
        };
        (foil, th)
    }
}

/// RMS and max |ΔCp| over the nodes (TE node excluded: the exact speed there is zero at a
/// finite-angle corner), and the Cl error.
fn errors(kt: &KarmanTrefftz, panels: usize, alpha_deg: f64) -> (f64, f64, f64) {
    let alpha = alpha_deg.to_radians();
    let (foil, th) = kt.nodes(panels);
    let sys = PanelSystem::new(&foil).unwrap();
    assert!(sys.geometry().te.sharp);
    let sol = sys.solve(alpha_deg, 0.0).unwrap();
    let (mut sum, mut max) = (0.0, 0.0_f64);
    let inner = 1..panels;
    for i in inner.clone() {
        let q = kt.speed(th[i], alpha);
        let dcp = (sol.cp[i] - (1.0 - q * q)).abs();
        sum += dcp * dcp;
        max = max.max(dcp);
    }
    let rms = (sum / inner.len() as f64).sqrt();
    let cl_exact = 2.0 * kt.circulation(alpha) / kt.chord();
    (rms, max, (sol.cl - cl_exact).abs())
}

/// Cp and Cl errors fall at second order with panel count (each doubling of N cuts them by
/// more than 3×; measured ≈ 4×), and Cl tends to the exact Kutta–Joukowski value.
#[test]
fn karman_trefftz_convergence() {
    let kt = KarmanTrefftz::new(0.08, 0.06, 10.0);
    let alpha_deg: f64 = 5.0;
    let cl_exact = 2.0 * kt.circulation(alpha_deg.to_radians()) / kt.chord();
    let mut prev = (f64::INFINITY, f64::INFINITY);
    for panels in [40, 80, 160, 320] {
        let (rms, max, dcl) = errors(&kt, panels, alpha_deg);
        println!(
            "N = {panels}: rms |dCp| = {rms:.2e}, max |dCp| = {max:.2e}, |dCl| = {dcl:.2e} (Cl exact {cl_exact:.4})"
        );
        assert!(
            rms * 3.0 < prev.0,
            "rms Cp error did not fall enough at N = {panels}"
        );
        assert!(
            dcl * 3.0 < prev.1,
            "Cl error did not fall enough at N = {panels}"
        );
        prev = (rms, dcl);
    }
    assert!(prev.0 < 2.0e-3, "rms Cp error at N = 320: {}", prev.0);
    assert!(
        prev.1 < 1.0e-4 * cl_exact,
        "Cl error at N = 320: {}",
        prev.1
    );
}

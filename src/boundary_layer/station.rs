//! One boundary-layer station: primary variables and the secondary variables derived from
//! them (XFOIL xblsys.f BLPRV → BLKIN → BLVAR), including the Karman–Tsien edge-speed
//! correction, the edge Mach number and the Sutherland viscosity.

use super::amplification::amplification_rate_d;
use super::closures::{
    bl_thickness_d, ctau_eq_sqrt_d, density_shape_factor_d, dissipation_outer_d,
    dissipation_turbulent_d, kinematic_shape_factor_d, laminar_dissipation_d,
    laminar_energy_shape_factor_d, laminar_skin_friction_d, laminar_wake_dissipation_d,
    slip_velocity_d, turbulent_energy_shape_factor_d, turbulent_skin_friction_d,
};
use super::params::{BlParams, FlowConstants, Regime};
use super::BlError;
use super::{Dual, NVARS};
use crate::compressibility::GAMMA_MINUS_ONE;

/// Primary variables of one station (XFOIL BLPRV arguments).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct StationVars {
    /// ξ: arc length from the stagnation point, chord units (XFOIL XSSI).
    pub x: f64,
    /// Incompressible edge speed Ue/V∞ from the panel solution (XFOIL UEDG).
    pub u: f64,
    /// Momentum thickness θ (XFOIL THET).
    pub theta: f64,
    /// Displacement thickness δ*, including the wake gap in the wake (XFOIL DSTR).
    pub dstar: f64,
    /// Amplification factor N (laminar) or √Cτ (turbulent, wake) (XFOIL CTAU).
    pub s: f64,
    /// Wake gap thickness (0 on the airfoil; XFOIL DSWAKI / WGAP).
    pub dw: f64,
}

/// Secondary variables of a station as derivative numbers (XFOIL COM2 block; the names are the
/// symbols of the equations, XFOIL's without the station suffix).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Station<const N: usize = NVARS> {
    /// ξ (XFOIL X2).
    pub x: Dual<N>,
    /// Compressible edge speed (XFOIL U2).
    pub u: Dual<N>,
    /// Momentum thickness θ (XFOIL T2).
    pub t: Dual<N>,
    /// δ* − wake gap (XFOIL D2).
    pub d: Dual<N>,
    /// N or √Cτ (XFOIL S2).
    pub s: Dual<N>,
    /// Wake gap (XFOIL DW2).
    pub dw: f64,
    /// Edge Mach number squared (XFOIL M2).
    pub msq: Dual<N>,
    /// Edge density ρe/ρ∞ (XFOIL R2).
    pub rho: Dual<N>,
    /// Shape parameter H = δ*/θ (XFOIL H2).
    pub h: Dual<N>,
    /// Kinematic shape parameter Hk, clamped (XFOIL HK2).
    pub hk: Dual<N>,
    /// Momentum-thickness Reynolds number Re_θ (XFOIL RT2).
    pub rt: Dual<N>,
    /// Density shape parameter H** (XFOIL HC2).
    pub hc: Dual<N>,
    /// Kinetic-energy shape parameter H* (XFOIL HS2).
    pub hs: Dual<N>,
    /// Normalised slip velocity Us (XFOIL US2).
    pub us: Dual<N>,
    /// Equilibrium √Cτ (XFOIL CQ2).
    pub cq: Dual<N>,
    /// Skin-friction coefficient Cf (XFOIL CF2).
    pub cf: Dual<N>,
    /// Dissipation 2CD/H* (XFOIL DI2).
    pub di: Dual<N>,
    /// Boundary-layer thickness δ (XFOIL DE2).
    pub de: Dual<N>,
    /// Envelope amplification rate dN/dξ (laminar stations; zero in the other regimes),
    /// evaluated once with the station and shared by every interval and transition check
    /// that averages it.
    pub ax: Dual<N>,
}

/// Checks that a station's primary variables are usable (finite, positive where needed).
pub(crate) fn validate(v: &StationVars, regime: Regime) -> Result<(), BlError> {
    let checks: [(&'static str, f64, bool); 5] = [
        ("xi", v.x, v.x > 0.0),
        ("edge speed", v.u, v.u > 0.0),
        ("theta", v.theta, v.theta > 0.0),
        ("dstar minus wake gap", v.dstar - v.dw, v.dstar - v.dw > 0.0),
        (
            "shear variable",
            v.s,
            regime == Regime::Laminar || v.s > 0.0,
        ),
    ];
    for (what, value, ok) in checks {
        if !(value.is_finite() && ok) {
            return Err(BlError::Station { what, value });
        }
    }
    if !v.dw.is_finite() || v.dw < 0.0 {
        return Err(BlError::Station {
            what: "wake gap",
            value: v.dw,
        });
    }
    Ok(())
}

/// Karman–Tsien compressible edge speed (XFOIL BLPRV): Ue = Ui(1−λ)/(1−λUi²).
pub(crate) fn compressible_speed_d<const N: usize>(ui: Dual<N>, fc: &FlowConstants) -> Dual<N> {
    fc.karman_tsien.speed_of(ui)
}

impl Station {
    /// Station from its primary variables, seeded in gradient slots
    /// `offset..offset+5` in the order (s, θ, δ*, u, ξ); `None` makes all constants.
    /// The secondary variables are computed on 4-slot numbers and then embedded.
    pub fn seeded(
        v: &StationVars,
        offset: Option<usize>,
        regime: Regime,
        fc: &FlowConstants,
        p: &BlParams,
    ) -> Self {
        match offset {
            Some(offset) => Station::own(v, regime, fc, p).embed(offset),
            None => Station::constant(v, regime, fc, p),
        }
    }
}

impl Station<4> {
    /// Station from its primary variables with derivatives with respect to its own variables
    /// (s, θ, δ*, u) in slots 0..4; ξ is held fixed. No secondary variable depends on ξ, so
    /// [`Station::embed`] adds its slot afterwards: the local iterations of a march, which
    /// vary (s, θ, δ*, u) at fixed ξ, need no more, and the others one slot more.
    pub fn own(v: &StationVars, regime: Regime, fc: &FlowConstants, p: &BlParams) -> Self {
        let s = Dual::variable(v.s, 0);
        let t = Dual::variable(v.theta, 1);
        let d = Dual::variable(v.dstar, 2) - v.dw;
        let u = compressible_speed_d(Dual::variable(v.u, 3), fc);
        let x = Dual::constant(v.x);
        Station::from_primaries(x, u, t, d, s, v.dw, regime, fc, p)
    }
}

impl<const N: usize> Station<N> {
    /// Station from its primary variables with all `N` derivative slots zero: the values of
    /// [`Station::seeded`] (every operation acts on the value and on each slot separately, so
    /// the number of slots does not change any value), for callers that need values only or
    /// seed their own variable, e.g. N2 in the transition check.
    pub fn constant(v: &StationVars, regime: Regime, fc: &FlowConstants, p: &BlParams) -> Self {
        let c = Dual::<N>::constant;
        let s = c(v.s);
        let t = c(v.theta);
        let d = c(v.dstar) - v.dw;
        let u = compressible_speed_d(c(v.u), fc);
        let x = c(v.x);
        Station::from_primaries(x, u, t, d, s, v.dw, regime, fc, p)
    }
}

impl Station<4> {
    /// The station with its derivatives with respect to (s, θ, δ*, u) placed at slots
    /// `offset..offset+4` of an `M`-slot number and ξ seeded in slot `offset + 4`: the same
    /// numbers as an evaluation with all five variables seeded there (each slot of a
    /// derivative number is computed on its own, and no secondary variable depends on ξ).
    pub fn embed<const M: usize>(&self, offset: usize) -> Station<M> {
        let e = |d: Dual<4>| d.embed::<M>(offset);
        Station {
            x: Dual::variable(self.x.v, offset + 4),
            u: e(self.u),
            t: e(self.t),
            d: e(self.d),
            s: e(self.s),
            dw: self.dw,
            msq: e(self.msq),
            rho: e(self.rho),
            h: e(self.h),
            hk: e(self.hk),
            rt: e(self.rt),
            hc: e(self.hc),
            hs: e(self.hs),
            us: e(self.us),
            cq: e(self.cq),
            cf: e(self.cf),
            di: e(self.di),
            de: e(self.de),
            ax: e(self.ax),
        }
    }
}

impl<const N: usize> Station<N> {
    /// The same station's values with `M` zero derivative slots: a station held fixed while
    /// the derivatives with respect to another station's variables are taken (each slot of a
    /// derivative number is computed on its own, so a slot that is zero here is zero in the
    /// embedded form too), or with `M` = 0 its values alone.
    pub fn frozen<const M: usize>(&self) -> Station<M> {
        let z = |d: Dual<N>| Dual::<M>::constant(d.v);
        Station {
            x: z(self.x),
            u: z(self.u),
            t: z(self.t),
            d: z(self.d),
            s: z(self.s),
            dw: self.dw,
            msq: z(self.msq),
            rho: z(self.rho),
            h: z(self.h),
            hk: z(self.hk),
            rt: z(self.rt),
            hc: z(self.hc),
            hs: z(self.hs),
            us: z(self.us),
            cq: z(self.cq),
            cf: z(self.cf),
            di: z(self.di),
            de: z(self.de),
            ax: z(self.ax),
        }
    }

    /// [`Station::frozen`] with ξ alone seeded, in slot `slot`: a station held fixed except
    /// for its position (the ξ column of its Jacobian).
    pub fn frozen_but_xi<const M: usize>(&self, slot: usize) -> Station<M> {
        Station {
            x: Dual::variable(self.x.v, slot),
            ..self.frozen()
        }
    }

    /// Secondary variables from primaries given as derivative numbers (compressible `u`,
    /// `d` = δ* − wake gap): XFOIL BLKIN followed by BLVAR.
    #[allow(clippy::too_many_arguments)]
    pub fn from_primaries(
        x: Dual<N>,
        u: Dual<N>,
        t: Dual<N>,
        d: Dual<N>,
        s: Dual<N>,
        dw: f64,
        regime: Regime,
        fc: &FlowConstants,
        p: &BlParams,
    ) -> Self {
        // BLKIN: edge Mach², density, viscosity (Sutherland), H, Hk, Re_θ.
        let gm1 = GAMMA_MINUS_ONE;
        let u2h = u.sq() * fc.inverse_stagnation_enthalpy;
        let msq = u2h / ((1.0 - u2h * 0.5) * gm1);
        let tr = msq * (0.5 * gm1) + 1.0;
        let rho = tr.powf(-1.0 / gm1) * fc.stagnation_density_ratio;
        let herat = 1.0 - u2h * 0.5;
        let hvrat = fc.sutherland_ratio;
        let visc = herat * herat.sqrt() * (1.0 + hvrat) / (herat + hvrat) / fc.stagnation_reynolds;
        let h = d / t;
        let hk_raw = kinematic_shape_factor_d(h, msq);
        let rt = rho * u * t / visc;

        // BLVAR: clamp Hk, then H**, H*, Us, √Cτ_eq, Cf, 2CD/H*, δ.
        let hk = match regime {
            Regime::Wake => hk_raw.max_const(p.hk_min_wake),
            _ => hk_raw.max_const(p.hk_min_wall),
        };
        let hc = density_shape_factor_d(hk, msq);
        let hs = match regime {
            Regime::Laminar => laminar_energy_shape_factor_d(hk),
            _ => turbulent_energy_shape_factor_d(hk, rt, msq),
        };
        let us_raw = slip_velocity_d(hs, hk, h, p.equilibrium_locus_b);
        let us = match regime {
            Regime::Wake if us_raw.v > 0.99995 => Dual::constant(0.99995),
            Regime::Laminar | Regime::Turbulent if us_raw.v > 0.95 => Dual::constant(0.98),
            _ => us_raw,
        };
        let cq = ctau_eq_sqrt_d(
            hs,
            us,
            hk,
            h,
            rt,
            regime == Regime::Turbulent,
            p.equilibrium_ctau_constant(),
            p.equilibrium_low_re_offset,
        );
        // Cf and 2CD/H* per regime; the turbulent Cf enters both.
        let (cf, di) = match regime {
            Regime::Laminar => (
                laminar_skin_friction_d(hk, rt),
                laminar_dissipation_d(hk, rt),
            ),
            Regime::Turbulent => {
                let ct = turbulent_skin_friction_d(hk, rt, msq);
                let cl = laminar_skin_friction_d(hk, rt);
                let cf = if cl.v > ct.v { cl } else { ct };
                let dt = dissipation_turbulent_d(hs, us, ct, s, hk, rt);
                let dl = laminar_dissipation_d(hk, rt);
                (cf, if dl.v > dt.v { dl } else { dt })
            }
            Regime::Wake => {
                let dt = dissipation_outer_d(hs, us, s, rt);
                let dl = laminar_wake_dissipation_d(hk, rt);
                // two wake halves
                (
                    Dual::constant(0.0),
                    (if dl.v > dt.v { dl } else { dt }) * 2.0,
                )
            }
        };
        let de = bl_thickness_d(hk, t, d);
        let ax = match regime {
            Regime::Laminar => amplification_rate_d(hk, t, rt),
            _ => Dual::constant(0.0),
        };
        Self {
            x,
            u,
            t,
            d,
            s,
            dw,
            msq,
            rho,
            h,
            hk,
            rt,
            hc,
            hs,
            us,
            cq,
            cf,
            di,
            de,
            ax,
        }
    }
}

/// Boundary-layer quantities of one station for output (distributions, diagnostics).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct StationProperties {
    /// Compressible edge speed Ue/V∞ (Karman–Tsien).
    pub ue: f64,
    /// Edge Mach number squared.
    pub mach_edge_sq: f64,
    /// Edge density ρe/ρ∞ (isentropic).
    pub rho_edge: f64,
    /// Shape parameter H = δ*/θ (δ* without the wake gap).
    pub h: f64,
    /// Kinematic shape parameter Hk (after the regime's lower clamp).
    pub hk: f64,
    /// Momentum-thickness Reynolds number Re_θ (edge density and viscosity).
    pub re_theta: f64,
    /// Kinetic-energy shape parameter H*.
    pub h_star: f64,
    /// Skin-friction coefficient Cf based on edge dynamic pressure (0 in the wake).
    pub cf: f64,
    /// Dissipation coefficient CD = (2CD/H*)·H*/2.
    pub cd: f64,
    /// Equilibrium √Cτ.
    pub ctau_eq_sqrt: f64,
    /// Wall shear stress over ρ∞V∞², τw = ½ρe Ue² Cf (XFOIL TAU; Cf based on free-stream
    /// dynamic pressure is 2τw).
    pub tau_wall: f64,
    /// Dissipation integral over ρ∞V∞³, ρe Ue³ CD (XFOIL DIS).
    pub dissipation: f64,
    /// Normalised slip velocity Us.
    pub us: f64,
    /// Boundary-layer thickness δ (Green's correlation).
    pub delta: f64,
}

impl StationProperties {
    pub(crate) fn from_station<const N: usize>(st: &Station<N>) -> Self {
        Self {
            ue: st.u.v,
            mach_edge_sq: st.msq.v,
            rho_edge: st.rho.v,
            h: st.h.v,
            hk: st.hk.v,
            re_theta: st.rt.v,
            h_star: st.hs.v,
            cf: st.cf.v,
            cd: 0.5 * st.di.v * st.hs.v,
            ctau_eq_sqrt: st.cq.v,
            tau_wall: 0.5 * st.rho.v * st.u.v * st.u.v * st.cf.v,
            dissipation: st.rho.v * st.u.v.powi(3) * 0.5 * st.di.v * st.hs.v,
            us: st.us.v,
            delta: st.de.v,
        }
    }
}

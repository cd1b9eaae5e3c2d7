//! Clipping of polylines to the axes (plotters draws outside the plot area otherwise) and the
//! breaking of lines at missing (non-finite) values.

/// Liang–Barsky clipping of the segment a→b to the rectangle `[x0, x1] × [y0, y1]`
/// (Liang & Barsky 1984, parametric line clipping). `None` when it lies outside.
fn clip_segment(
    a: (f64, f64),
    b: (f64, f64),
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let mut t0: f64 = 0.0;
    let mut t1: f64 = 1.0;
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            (a.0 + t * dx, a.1 + t * dy)
        }
    };
    Some((at(t0), at(t1)))
}

/// Splits a polyline at non-finite points and clips it to the axes: the visible pieces.
pub(crate) fn visible_pieces(
    points: &[(f64, f64)],
    xlim: (f64, f64),
    ylim: (f64, f64),
) -> Vec<Vec<(f64, f64)>> {
    let mut pieces: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
    for w in points.windows(2) {
        let clipped = if finite(&w[0]) && finite(&w[1]) {
            clip_segment(w[0], w[1], xlim, ylim)
        } else {
            None
        };
        match clipped {
            Some((a, b)) => {
                if current.last() != Some(&a) {
                    if current.len() > 1 {
                        pieces.push(std::mem::take(&mut current));
                    }
                    current.clear();
                    current.push(a);
                }
                current.push(b);
            }
            None => {
                if current.len() > 1 {
                    pieces.push(std::mem::take(&mut current));
                }
                current.clear();
            }
        }
    }
    if current.len() > 1 {
        pieces.push(current);
    }
    pieces
}

/// Whether (x, y) lies inside the axes.
pub(super) fn inside(pt: (f64, f64), (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> bool {
    pt.0 >= x0 && pt.0 <= x1 && pt.1 >= y0 && pt.1 <= y1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping_cuts_lines_at_the_axes() {
        let pts = [
            (-1.0, 0.5),
            (0.5, 0.5),
            (2.0, 0.5),
            (f64::NAN, 0.0),
            (0.2, 0.2),
            (0.4, 0.4),
        ];
        let pieces = visible_pieces(&pts, (0.0, 1.0), (0.0, 1.0));
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0], vec![(0.0, 0.5), (0.5, 0.5), (1.0, 0.5)]);
        assert_eq!(pieces[1], vec![(0.2, 0.2), (0.4, 0.4)]);
        assert!(clip_segment((2.0, 2.0), (3.0, 3.0), (0.0, 1.0), (0.0, 1.0)).is_none());
    }
}

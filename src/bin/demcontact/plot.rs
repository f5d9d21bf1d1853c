//! The fit figure: measured e against impact speed (log axis), with both fitted models.

use crate::csv::Table;
use crate::output::Failure;
use demcontact::EndCriterion;
use demcontact::fit::Fit;
use demcontact::viscoelastic::full_range::e_full;
use plotters::prelude::*;
use plotters::style::FontStyle;
use std::path::Path;

fn load_font() -> Result<(), String> {
    let candidates = [
        std::env::var("DC_REPORT_FONT").unwrap_or_default(),
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf".to_string(),
        "/usr/share/fonts/TTF/DejaVuSans.ttf".to_string(),
        "/usr/share/fonts/dejavu/DejaVuSans.ttf".to_string(),
    ];
    for path in candidates.iter().filter(|p| !p.is_empty()) {
        if let Ok(bytes) = std::fs::read(path) {
            // plotters keeps the font for the life of the program.
            let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
            return plotters::style::register_font("sans-serif", FontStyle::Normal, bytes)
                .map_err(|_| format!("{path}: not a usable font"));
        }
    }
    Err("no DejaVuSans.ttf found (install fonts-dejavu-core or set DC_REPORT_FONT)".into())
}

pub fn fit_figure(path: &Path, t: &Table, f: &Fit, crit: EndCriterion) -> Result<(), Failure> {
    let name = path.display().to_string();
    let fail = |e: String| Failure::output(&name, e);
    load_font().map_err(fail)?;
    draw(path, t, f, crit).map_err(|e| Failure::output(&name, e))
}

fn draw(path: &Path, t: &Table, f: &Fit, crit: EndCriterion) -> Result<(), String> {
    let root = BitMapBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let (lo, hi) = (f.v_min / 1.5, f.v_max * 1.5);
    let sig = |i: usize| {
        t.sigma
            .as_ref()
            .and_then(|s| s.get(i).copied())
            .unwrap_or(0.0)
    };
    let mut e_lo: f64 = 1.0;
    let mut e_hi: f64 = 0.0;
    for (i, &e) in t.e.iter().enumerate() {
        e_lo = e_lo.min(e - sig(i));
        e_hi = e_hi.max(e + sig(i));
    }
    let curve = |v: f64| e_full(f.beta * v.powf(0.2), crit).unwrap_or(f64::NAN);
    e_lo = e_lo.min(curve(hi)).min(f.e_const) - 0.02;
    e_hi = e_hi.max(curve(lo)).max(f.e_const) + 0.02;
    let mut chart = ChartBuilder::on(&root)
        .caption("measured restitution and the two fits", ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d((lo..hi).log_scale(), e_lo.max(0.0)..e_hi.min(1.05))
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc("impact speed v [m/s]")
        .y_desc("restitution e")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| e.to_string())?;
    let n = 200;
    let pts: Vec<(f64, f64)> = (0..=n)
        .map(|k| {
            let v = lo * (hi / lo).powf(f64::from(k) / f64::from(n));
            (v, curve(v))
        })
        .collect();
    chart
        .draw_series(LineSeries::new(pts, BLUE.stroke_width(2)))
        .map_err(|e| e.to_string())?
        .label(format!(
            "viscoelastic, beta = {:.4e} ± {:.1e}",
            f.beta, f.beta_se
        ))
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE.stroke_width(2)));
    chart
        .draw_series(LineSeries::new(
            vec![(lo, f.e_const), (hi, f.e_const)],
            RED.stroke_width(2),
        ))
        .map_err(|e| e.to_string())?
        .label(format!(
            "constant e = {:.4} ± {:.1e}",
            f.e_const, f.e_const_se
        ))
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RED.stroke_width(2)));
    let data: Vec<(f64, f64, f64)> =
        t.v.iter()
            .zip(&t.e)
            .enumerate()
            .map(|(i, (&v, &e))| (v, e, sig(i)))
            .collect();
    chart
        .draw_series(data.iter().filter(|d| d.2 > 0.0).map(|&(v, e, s)| {
            PathElement::new(vec![(v, e - s), (v, e + s)], BLACK.stroke_width(1))
        }))
        .map_err(|e| e.to_string())?;
    chart
        .draw_series(
            data.iter()
                .map(|&(v, e, _)| Circle::new((v, e), 4, BLACK.filled())),
        )
        .map_err(|e| e.to_string())?
        .label("measured")
        .legend(|(x, y)| Circle::new((x + 10, y), 4, BLACK.filled()));
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .label_font(("sans-serif", 15))
        .draw()
        .map_err(|e| e.to_string())?;
    root.present().map_err(|e| e.to_string())?;
    Ok(())
}

//! A small line/scatter plotting layer over plotters' bitmap backend: panels with optional log
//! axes (values plotted as log10 with 1eN labels), legends, PNG output. Text uses a TrueType font
//! loaded at run time (DejaVu Sans from fonts-dejavu-core, installed by scripts/setup.sh), so no
//! system font library is needed.

use plotters::prelude::*;

/// Any failure, as its message (no `Debug` on purpose: that keeps the blanket `From` legal, so
/// `?` works on library, plotters and I/O errors alike).
pub struct Fail(pub String);

impl<E: std::fmt::Debug> From<E> for Fail {
    fn from(e: E) -> Self {
        Fail(format!("{e:?}"))
    }
}

pub type Res<T> = Result<T, Fail>;

#[derive(Clone, Copy, PartialEq)]
pub enum Kind {
    Line,
    Dashed,
    Points,
    LinePoints,
}

pub struct Series {
    pub name: String,
    pub pts: Vec<(f64, f64)>,
    pub kind: Kind,
    pub color: usize,
}

impl Series {
    pub fn new(name: impl Into<String>, pts: Vec<(f64, f64)>, kind: Kind, color: usize) -> Self {
        Series {
            name: name.into(),
            pts,
            kind,
            color,
        }
    }
}

pub struct Panel {
    pub title: String,
    pub xlabel: String,
    pub ylabel: String,
    pub logx: bool,
    pub logy: bool,
    pub series: Vec<Series>,
    /// Fixed y range (in data units) instead of the data's.
    pub yrange: Option<(f64, f64)>,
    pub legend_pos: SeriesLabelPosition,
}

impl Panel {
    pub fn new(
        title: impl Into<String>,
        xlabel: impl Into<String>,
        ylabel: impl Into<String>,
    ) -> Self {
        Panel {
            title: title.into(),
            xlabel: xlabel.into(),
            ylabel: ylabel.into(),
            logx: false,
            logy: false,
            series: Vec::new(),
            yrange: None,
            legend_pos: SeriesLabelPosition::UpperLeft,
        }
    }
    pub fn log(mut self, x: bool, y: bool) -> Self {
        self.logx = x;
        self.logy = y;
        self
    }
    pub fn legend(mut self, pos: SeriesLabelPosition) -> Self {
        self.legend_pos = pos;
        self
    }
    pub fn yrange(mut self, lo: f64, hi: f64) -> Self {
        self.yrange = Some((lo, hi));
        self
    }
    pub fn add(&mut self, s: Series) {
        self.series.push(s);
    }
}

const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(90, 90, 90),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

pub fn color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

/// Registers the TrueType font plotters draws text with.
pub fn load_font() -> Res<()> {
    let candidates = [
        std::env::var("DC_REPORT_FONT").unwrap_or_default(),
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf".to_string(),
        "/usr/share/fonts/TTF/DejaVuSans.ttf".to_string(),
        "/usr/share/fonts/dejavu/DejaVuSans.ttf".to_string(),
    ];
    for path in candidates.iter().filter(|p| !p.is_empty()) {
        if let Ok(bytes) = std::fs::read(path) {
            let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
            plotters::style::register_font("sans-serif", FontStyle::Normal, bytes)
                .map_err(|_| Fail(format!("{path}: not a usable font")))?;
            return Ok(());
        }
    }
    Err(Fail("no DejaVuSans.ttf found: run scripts/setup.sh (installs fonts-dejavu-core) or set DC_REPORT_FONT".into()))
}

fn tr(v: f64, log: bool) -> Option<f64> {
    if log {
        if v > 0.0 && v.is_finite() {
            Some(v.log10())
        } else {
            None
        }
    } else if v.is_finite() {
        Some(v)
    } else {
        None
    }
}

fn fmt_tick(v: f64, log: bool) -> String {
    if log {
        if (v - v.round()).abs() < 1e-9 {
            let k = v.round() as i32;
            match k {
                0 => "1".into(),
                1 => "10".into(),
                -1 => "0.1".into(),
                _ => format!("1e{k}"),
            }
        } else {
            String::new()
        }
    } else {
        let a = v.abs();
        if a == 0.0 {
            "0".into()
        } else if !(1e-3..1e4).contains(&a) {
            format!("{v:.0e}")
        } else {
            let s = format!("{v:.3}");
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        }
    }
}

/// Draws `panels` in a grid of `cols` columns into `path` (width × height per panel).
pub fn figure(path: &str, panels: &[Panel], cols: usize, size: (u32, u32)) -> Res<()> {
    let rows = panels.len().div_ceil(cols);
    let root =
        BitMapBackend::new(path, (size.0 * cols as u32, size.1 * rows as u32)).into_drawing_area();
    root.fill(&WHITE)?;
    let areas = root.split_evenly((rows, cols));
    for (panel, area) in panels.iter().zip(areas.iter()) {
        draw_panel(panel, area)?;
    }
    root.present()?;
    Ok(())
}

fn draw_panel(p: &Panel, area: &DrawingArea<BitMapBackend, plotters::coord::Shift>) -> Res<()> {
    let mut xs: Vec<f64> = Vec::new();
    let mut ys: Vec<f64> = Vec::new();
    for s in &p.series {
        for &(x, y) in &s.pts {
            if let (Some(x), Some(y)) = (tr(x, p.logx), tr(y, p.logy)) {
                xs.push(x);
                ys.push(y);
            }
        }
    }
    let span = |v: &[f64]| {
        let lo = v.iter().cloned().fold(f64::INFINITY, f64::min);
        let hi = v.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        if lo.is_finite() && hi > lo {
            (lo, hi)
        } else if lo.is_finite() {
            (lo - 0.5, lo + 0.5)
        } else {
            (0.0, 1.0)
        }
    };
    let (mut x0, mut x1) = span(&xs);
    let (mut y0, mut y1) = match p.yrange {
        Some((a, b)) => (tr(a, p.logy).unwrap_or(0.0), tr(b, p.logy).unwrap_or(1.0)),
        None => span(&ys),
    };
    let pad = |a: &mut f64, b: &mut f64, log: bool| {
        if log {
            // At least one full decade, so that a labelled tick (an integer power) is inside.
            let span = (*b - *a).max(1.0);
            let mid = 0.5 * (*a + *b);
            *a = (mid - 0.55 * span).min(*a - 0.05);
            *b = (mid + 0.55 * span).max(*b + 0.05);
        } else {
            let d = 0.04 * (*b - *a);
            *a -= d;
            *b += d;
        }
    };
    pad(&mut x0, &mut x1, p.logx);
    if p.yrange.is_none() {
        pad(&mut y0, &mut y1, p.logy);
    }
    let mut chart = ChartBuilder::on(area)
        .caption(&p.title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(66)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    let (lx, ly) = (p.logx, p.logy);
    let fx = move |v: &f64| fmt_tick(*v, lx);
    let fy = move |v: &f64| fmt_tick(*v, ly);
    let nx = if lx {
        ((x1 - x0).round() as usize + 1).clamp(2, 12)
    } else {
        8
    };
    let ny = if ly {
        ((y1 - y0).round() as usize + 1).clamp(2, 12)
    } else {
        8
    };
    chart
        .configure_mesh()
        .x_desc(&p.xlabel)
        .y_desc(&p.ylabel)
        .x_labels(nx)
        .y_labels(ny)
        .x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .light_line_style(WHITE.mix(0.0))
        .draw()?;
    for s in &p.series {
        let c = color(s.color);
        let pts: Vec<(f64, f64)> = s
            .pts
            .iter()
            .filter_map(|&(x, y)| Some((tr(x, lx)?, tr(y, ly)?)))
            .filter(|&(_, y)| p.yrange.is_none() || (y >= y0 && y <= y1))
            .collect();
        let legend_line = move |(x, y): (i32, i32)| {
            PathElement::new(vec![(x, y), (x + 22, y)], c.stroke_width(2))
        };
        match s.kind {
            Kind::Line | Kind::LinePoints => {
                let anno = chart.draw_series(LineSeries::new(pts.clone(), c.stroke_width(2)))?;
                if !s.name.is_empty() {
                    anno.label(s.name.as_str()).legend(legend_line);
                }
                if s.kind == Kind::LinePoints {
                    chart.draw_series(pts.iter().map(|&q| Circle::new(q, 3, c.filled())))?;
                }
            }
            Kind::Dashed => {
                // Dashes by hand: plotters' DashedLineSeries needs an extra feature.
                let mut segs = Vec::new();
                for w in pts.windows(2) {
                    let (a, b) = (w[0], w[1]);
                    // Dash length ~1/60 of the panel, in plotted (possibly log) units.
                    let len = (((b.0 - a.0) / (x1 - x0)).powi(2)
                        + ((b.1 - a.1) / (y1 - y0)).powi(2))
                    .sqrt();
                    let n = ((len * 60.0).ceil() as usize).max(2) * 2;
                    for k in 0..n {
                        if k % 2 == 0 {
                            let t0 = k as f64 / n as f64;
                            let t1 = (k + 1) as f64 / n as f64;
                            segs.push(vec![
                                (a.0 + t0 * (b.0 - a.0), a.1 + t0 * (b.1 - a.1)),
                                (a.0 + t1 * (b.0 - a.0), a.1 + t1 * (b.1 - a.1)),
                            ]);
                        }
                    }
                }
                let anno = chart.draw_series(
                    segs.into_iter()
                        .map(|v| PathElement::new(v, c.stroke_width(2))),
                )?;
                if !s.name.is_empty() {
                    anno.label(s.name.as_str()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 8, y)], c.stroke_width(2))
                    });
                }
            }
            Kind::Points => {
                let anno = chart.draw_series(pts.iter().map(|&q| Circle::new(q, 4, c.filled())))?;
                if !s.name.is_empty() {
                    anno.label(s.name.as_str())
                        .legend(move |(x, y)| Circle::new((x + 11, y), 4, c.filled()));
                }
            }
        }
    }
    chart
        .configure_series_labels()
        .position(p.legend_pos.clone())
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.5))
        .label_font(("sans-serif", 13))
        .draw()?;
    Ok(())
}

//! A small CSV reader for restitution data: columns v, e and optionally sigma.
//!
//! Comma-, semicolon- or whitespace-separated; `#` starts a comment; blank lines are skipped; an
//! optional header line names the columns (v|speed|velocity, e|restitution|cor,
//! sigma|err|uncertainty|u_e, any order); without a header the columns are v, e[, sigma]. Every
//! error names the file, line and column (1-based, in characters).

use crate::output::Failure;

/// The parsed data.
#[derive(Debug, Default)]
pub struct Table {
    pub v: Vec<f64>,
    pub e: Vec<f64>,
    pub sigma: Option<Vec<f64>>,
    /// Line of each point (for messages).
    pub line: Vec<usize>,
}

/// Fields of a line with their 1-based start columns.
fn fields(line: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start: Option<usize> = None;
    let mut col = 0usize;
    let mut byte_start = 0usize;
    for (b, ch) in line.char_indices() {
        col += 1;
        let sep = ch == ',' || ch == ';' || ch.is_whitespace();
        match (sep, start) {
            (true, Some(c)) => {
                out.push((c, line.get(byte_start..b).unwrap_or("")));
                start = None;
            }
            (false, None) => {
                start = Some(col);
                byte_start = b;
            }
            _ => {}
        }
    }
    if let Some(c) = start {
        out.push((c, line.get(byte_start..).unwrap_or("")));
    }
    out
}

fn role(name: &str) -> Option<usize> {
    match name.to_ascii_lowercase().as_str() {
        "v" | "speed" | "velocity" | "v_impact" | "impact_speed" => Some(0),
        "e" | "restitution" | "cor" | "e_measured" => Some(1),
        "sigma" | "err" | "error" | "uncertainty" | "u_e" | "sigma_e" => Some(2),
        _ => None,
    }
}

/// Parses `text` read from `file`.
pub fn parse(file: &str, text: &str) -> Result<Table, Failure> {
    let mut t = Table::default();
    let mut cols: Option<[Option<usize>; 3]> = None; // field index of v, e, sigma
    let mut sig: Vec<f64> = Vec::new();
    for (ln0, raw) in text.lines().enumerate() {
        let ln = ln0 + 1;
        let line = raw.split('#').next().unwrap_or("");
        let f = fields(line);
        if f.is_empty() {
            continue;
        }
        let Some(&(c0, first)) = f.first() else {
            continue;
        };
        if cols.is_none() {
            if first.parse::<f64>().is_err() {
                // Header line.
                let mut map = [None; 3];
                for (i, &(c, name)) in f.iter().enumerate() {
                    match role(name) {
                        Some(r) => {
                            if let Some(slot) = map.get_mut(r) {
                                *slot = Some(i);
                            }
                        }
                        None => {
                            return Err(Failure::input(
                                file,
                                ln,
                                c,
                                format!(
                                    "unknown column '{name}' (expected v, e and optionally sigma)"
                                ),
                            ));
                        }
                    }
                }
                if map.first().is_none_or(|x| x.is_none()) || map.get(1).is_none_or(|x| x.is_none())
                {
                    return Err(Failure::input(
                        file,
                        ln,
                        c0,
                        "the header needs columns v and e".into(),
                    ));
                }
                cols = Some(map);
                continue;
            }
            cols = Some([Some(0), Some(1), if f.len() >= 3 { Some(2) } else { None }]);
        }
        let map = cols.unwrap_or([Some(0), Some(1), None]);
        let width = map.iter().flatten().max().map_or(0, |m| m + 1);
        if f.len() != width {
            let c = f
                .get(width)
                .map_or_else(|| line.chars().count() + 1, |x| x.0);
            return Err(Failure::input(
                file,
                ln,
                c,
                format!("expected {width} fields, found {}", f.len()),
            ));
        }
        let mut vals = [f64::NAN; 3];
        for (r, idx) in map.iter().enumerate() {
            let Some(i) = *idx else { continue };
            let Some(&(c, s)) = f.get(i) else { continue };
            let x: f64 = s
                .parse()
                .map_err(|_| Failure::input(file, ln, c, format!("'{s}' is not a number")))?;
            if !x.is_finite() {
                return Err(Failure::input(file, ln, c, format!("'{s}' is not finite")));
            }
            let ok = match r {
                0 => x > 0.0,
                1 => x > 0.0 && x <= 1.0,
                _ => x > 0.0,
            };
            if !ok {
                let why = match r {
                    0 => "impact speed must be > 0",
                    1 => "restitution must be in (0, 1]",
                    _ => "uncertainty must be > 0",
                };
                return Err(Failure::input(file, ln, c, format!("{s}: {why}")));
            }
            if let Some(slot) = vals.get_mut(r) {
                *slot = x;
            }
        }
        let [v, e, sg] = vals;
        t.v.push(v);
        t.e.push(e);
        if matches!(map, [_, _, Some(_)]) {
            sig.push(sg);
        }
        t.line.push(ln);
    }
    if matches!(cols, Some([_, _, Some(_)])) {
        t.sigma = Some(sig);
    }
    if t.v.is_empty() {
        return Err(Failure::input(file, 0, 0, "no data points".into()));
    }
    Ok(t)
}

//! Point files of `gec fit --input`: CSV (`x,y` or `x,y,z` rows, optional
//! header, `#` comments, `# open`) or JSON (an array of points or
//! `{"points": [...], "closed": bool}`); every coordinate finite, every
//! row the same width. The format is documented in `pdesculpt gec fit --help`.

/// A malformed points file (the message names the line or point).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct InputError(pub String);

/// Points of a file, with the 1-based line of each (CSV) and whether the
/// file declared the polyline open.
pub struct PointsFile {
    pub points: Vec<[f64; 3]>,
    pub lines: Option<Vec<usize>>,
    pub declared_open: bool,
    pub columns: usize,
}

/// Parses the CSV form (errors name the line).
pub fn parse_csv(text: &str) -> Result<PointsFile, InputError> {
    let mut points = Vec::new();
    let mut lines = Vec::new();
    let mut columns = 0;
    let mut declared_open = false;
    for (i, raw) in text.lines().enumerate() {
        let line_no = i + 1;
        let line = raw.trim();
        if line.is_empty() {
            continue;
        }
        if let Some(c) = line.strip_prefix('#') {
            if c.trim().eq_ignore_ascii_case("open") {
                declared_open = true;
            }
            continue;
        }
        let fields: Vec<&str> = line
            .split(|c: char| c == ',' || c == ';' || c.is_whitespace())
            .filter(|f| !f.is_empty())
            .collect();
        let nums: Vec<Result<f64, _>> = fields.iter().map(|f| f.parse::<f64>()).collect();
        if points.is_empty()
            && columns == 0
            && nums.iter().all(|r| r.is_err())
            && (2..=3).contains(&fields.len())
        {
            // header
            columns = fields.len();
            continue;
        }
        if !(2..=3).contains(&fields.len()) {
            return Err(InputError(format!(
                "line {line_no}: expected 2 or 3 numbers (x,y or x,y,z), found {} field(s): {line:?}",
                fields.len()
            )));
        }
        if columns != 0 && fields.len() != columns {
            return Err(InputError(format!(
                "line {line_no}: {} fields, but earlier rows have {columns}",
                fields.len()
            )));
        }
        columns = fields.len();
        let mut p = [0.0; 3];
        for (k, (f, r)) in fields.iter().zip(&nums).enumerate() {
            let v = r
                .as_ref()
                .map_err(|_| InputError(format!("line {line_no}: {f:?} is not a number")))?;
            if !v.is_finite() {
                return Err(InputError(format!(
                    "line {line_no}: coordinate {} is {f} (not finite)",
                    k + 1
                )));
            }
            p[k] = *v;
        }
        points.push(p);
        lines.push(line_no);
    }
    if points.is_empty() {
        return Err(InputError("no points in the file".into()));
    }
    Ok(PointsFile {
        points,
        lines: Some(lines),
        declared_open,
        columns,
    })
}

/// Parses the JSON form (errors name the point).
pub fn parse_json(text: &str) -> Result<PointsFile, InputError> {
    let v: serde_json::Value =
        serde_json::from_str(text).map_err(|e| InputError(format!("invalid JSON: {e}")))?;
    let (arr, declared_open) = match &v {
        serde_json::Value::Array(a) => (a, false),
        serde_json::Value::Object(o) => {
            let arr = o
                .get("points")
                .and_then(|p| p.as_array())
                .ok_or_else(|| InputError("the JSON object needs a \"points\" array".into()))?;
            let open = match o.get("closed") {
                None => false,
                Some(serde_json::Value::Bool(b)) => !b,
                Some(other) => {
                    return Err(InputError(format!(
                        "\"closed\" must be true or false, got {other}"
                    )))
                }
            };
            (arr, open)
        }
        _ => {
            return Err(InputError(
                "expected a JSON array of points or an object with \"points\"".into(),
            ))
        }
    };
    let mut points = Vec::with_capacity(arr.len());
    let mut columns = 0;
    for (i, p) in arr.iter().enumerate() {
        let c = p.as_array().ok_or_else(|| {
            InputError(format!("point {i}: expected [x, y] or [x, y, z], got {p}"))
        })?;
        if !(2..=3).contains(&c.len()) || (columns != 0 && c.len() != columns) {
            return Err(InputError(format!(
                "point {i}: expected {} coordinates, got {}",
                if columns == 0 {
                    "2 or 3".to_string()
                } else {
                    columns.to_string()
                },
                c.len()
            )));
        }
        columns = c.len();
        let mut q = [0.0; 3];
        for (k, x) in c.iter().enumerate() {
            q[k] = x.as_f64().filter(|v| v.is_finite()).ok_or_else(|| {
                InputError(format!("point {i}: coordinate {x} is not a finite number"))
            })?;
        }
        points.push(q);
    }
    if points.is_empty() {
        return Err(InputError("no points in the file".into()));
    }
    Ok(PointsFile {
        points,
        lines: None,
        declared_open,
        columns,
    })
}

/// Parses a points file: JSON when it starts with `[` or `{`, CSV otherwise.
pub fn parse_points(text: &str) -> Result<PointsFile, InputError> {
    if matches!(text.trim_start().chars().next(), Some('[') | Some('{')) {
        parse_json(text)
    } else {
        parse_csv(text)
    }
}

/// Largest magnitude of a coefficient or frame origin coordinate of a GEC
/// read from a file: with J <= [`crate::limits::CURVE_HARMONICS`] terms and
/// derivatives up to order 8, every value and derivative stays finite.
pub const MAX_COEFFICIENT: f64 = 1e100;

/// Refuses a GEC read from a file whose numbers are so large that its
/// points or derivatives would overflow (clear error instead of inf output).
pub fn check_magnitudes(g: &super::Gec) -> Result<(), InputError> {
    crate::limits::check("terms", g.terms(), crate::limits::CURVE_HARMONICS)
        .map_err(|e| InputError(e.to_string()))?;
    let nums =
        g.x.iter()
            .chain(&g.y)
            .flatten()
            .chain(&g.centre)
            .chain(&g.frame.origin);
    for x in nums {
        if x.is_nan() || x.abs() > MAX_COEFFICIENT {
            return Err(InputError(format!(
                "GEC number {x:e} is larger than {MAX_COEFFICIENT:e} in magnitude (values and derivatives would overflow; rescale the curve)"
            )));
        }
    }
    Ok(())
}

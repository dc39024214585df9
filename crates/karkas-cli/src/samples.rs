//! Parsing and defaults of `--samples`.

/// Parses `NU,NV` (each at least 2).
pub fn parse_pair(text: &str) -> Result<(usize, usize), String> {
    let (a, b) = text
        .split_once(',')
        .ok_or_else(|| format!("expected NU,NV (two counts separated by a comma), got '{text}'"))?;
    Ok((parse_count(a.trim())?, parse_count(b.trim())?))
}

/// Parses one sample count (at least 2).
pub fn parse_count(text: &str) -> Result<usize, String> {
    let n: usize = text
        .parse()
        .map_err(|_| format!("'{text}' is not a whole number"))?;
    if n < 2 {
        return Err(format!("at least 2 samples are needed, got {n}"));
    }
    Ok(n)
}

/// The default number of curve samples for `k` input points: 10 per point, at least 200.
pub fn default_curve_samples(k: usize) -> usize {
    (10 * k).max(200)
}

/// The default number of surface samples along a direction with `k` grid lines.
pub fn default_surface_samples(k: usize) -> usize {
    (4 * k).max(50)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_and_counts() {
        assert_eq!(parse_pair("10, 20"), Ok((10, 20)));
        assert!(parse_pair("10").is_err());
        assert!(parse_pair("1,5").is_err());
        assert!(parse_count("x").is_err());
        assert_eq!(default_curve_samples(5), 200);
        assert_eq!(default_curve_samples(53), 530);
    }
}

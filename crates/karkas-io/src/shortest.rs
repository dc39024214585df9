//! `f64` written as Rust's `{}` writes it (shortest round-trip digits, plain decimal, no
//! exponent: `1`, `-0`, `0.0001`, `100000000000000000000`), at the speed of `ryu`.
//!
//! Every CSV of this crate writes numbers in that form, and the files are a contract: the
//! same bytes before and after this module. `std`'s formatting machinery (`fmt::Display`
//! through a `Formatter`) costs several times more than the digit generation itself, and most
//! of a large CSV's writing time went there; `ryu` (Adams, "Ryū: fast float-to-string
//! conversion", PLDI 2018) yields the same shortest digits (both pick the shortest string that
//! reads back to the same `f64`, the nearest to the exact value among them) but in its own
//! layout (`1.0`, `1e20`, `1.5e-7`); [`push`] moves its digits into `{}`'s layout. The one
//! place they differ is an exact tie, a value halfway between two shortest candidates
//! (`125406270313.515625`, shortest in 17 digits): `ryu` rounds it to even, `std` up (away
//! from zero); [`push`] finds the tie exactly (integer arithmetic on the binary significand)
//! and rounds up as `std` does. Tests compare the bytes with `format!("{v}")` on random bit
//! patterns, on values with short binary fractions (where ties live), subnormals and extremes
//! included.
//!
//! [`push_debug`] writes `{:?}`'s form instead (`1.0`, `-0.0`, `1e-5`, `1e16`), which
//! `karkas inspect`'s report uses: for `1e-4 <= |v| < 1e16` the digits of `{}` with `.0` after a
//! whole number, outside it `std`'s own exponent form (rare in measured coordinates and
//! distances).

/// Appends `v` to `out` exactly as `format!("{v}")` writes it.
///
/// ```
/// let mut out = Vec::new();
/// karkas_io::shortest::push(&mut out, 100.0);
/// assert_eq!(out, b"100");
/// ```
#[inline]
pub fn push(out: &mut Vec<u8>, v: f64) {
    if v == 0.0 {
        out.extend_from_slice(if v.is_sign_negative() { b"-0" } else { b"0" });
        return;
    }
    if !v.is_finite() {
        out.extend_from_slice(format!("{v}").as_bytes());
        return;
    }
    let mut buffer = ryu::Buffer::new();
    let text = buffer.format_finite(v).as_bytes();
    // The commonest case, taken without looking at the text: `ryu` writes a plain decimal
    // for 1e-5 <= |v| < 1e16 (the range here stays a decade inside, whatever the rounding
    // of the digits), and a tie needs `v`'s lowest set bit at 2^-(f + 1) for the f digits
    // after the point, while a value whose lowest bit lies below 2^-len has more binary
    // places than the text has characters: no tie, and no `.0` of a whole number.
    if (1e-4..1e15).contains(&v.abs()) && lowest_bit(v) < -(text.len() as i64) {
        out.extend_from_slice(text);
        return;
    }
    // The common case: a plain decimal (`-911.7978476360678`, `0.00012`) is `{}`'s own
    // layout, and `123.0` is `123`; only a possible tie needs the digits taken apart.
    if !text.contains(&b'e') {
        if let Some(whole) = text.strip_suffix(b".0") {
            out.extend_from_slice(whole);
            return;
        }
        if let Some(point) = text.iter().position(|&b| b == b'.') {
            let fraction = (text.len() - point - 1) as i64;
            if lowest_bit(v) != -(fraction + 1) {
                out.extend_from_slice(text);
                return;
            }
        }
    }
    push_digits(out, v, text);
}

/// Appends `v` to `out` exactly as `format!("{v:?}")` writes it.
///
/// ```
/// let mut out = Vec::new();
/// for v in [100.0, -0.0, 0.1 + 0.2, 1.5e-7, 2e16] {
///     karkas_io::shortest::push_debug(&mut out, v);
///     out.push(b',');
/// }
/// assert_eq!(out, b"100.0,-0.0,0.30000000000000004,1.5e-7,2e16,");
/// ```
#[inline]
pub fn push_debug(out: &mut Vec<u8>, v: f64) {
    if v == 0.0 {
        out.extend_from_slice(if v.is_sign_negative() {
            b"-0.0"
        } else {
            b"0.0"
        });
        return;
    }
    if !(1e-4..1e16).contains(&v.abs()) {
        use std::io::Write as _;
        // Writing to a vector cannot fail.
        let _ = write!(out, "{v:?}");
        return;
    }
    let start = out.len();
    push(out, v);
    if !out[start..].contains(&b'.') {
        out.extend_from_slice(b".0");
    }
}

/// Appends `v` (finite, not zero) from `ryu`'s `text` when its digits must be taken apart:
/// an exponent to lay out as a plain decimal, or a possible tie to round up.
fn push_digits(out: &mut Vec<u8>, v: f64, text: &[u8]) {
    let (negative, text) = match text.split_first() {
        Some((b'-', rest)) => (true, rest),
        _ => (false, text),
    };
    let (mantissa, exponent) = match text.iter().position(|&b| b == b'e') {
        Some(k) => (&text[..k], exponent_of(&text[k + 1..])),
        None => (text, 0),
    };
    // The digits without the point, and where the point goes (digits before it).
    let mut digits = [0u8; 32];
    let (mut count, mut point) = (0usize, None);
    for &b in mantissa {
        if b == b'.' {
            point = Some(count);
        } else if count + 1 < digits.len() {
            digits[count] = b;
            count += 1;
        }
    }
    let mut point = point.unwrap_or(count) as i64 + exponent;
    // One free place in front for a carry of the rounding up of a tie.
    digits.copy_within(0..count, 1);
    digits[0] = b'0';
    let (mut start, count) = (1, count + 1);
    while start < count && digits[start] == b'0' {
        start += 1;
        point -= 1;
    }
    let mut end = count;
    while end > start && digits[end - 1] == b'0' {
        end -= 1;
    }
    if is_tie(v, &digits[start..end], point) {
        // Rounded up in the last digit; a carry may add a digit in front.
        let mut k = end;
        loop {
            if k == start {
                start -= 1;
                digits[start] = b'1';
                point += 1;
                break;
            }
            k -= 1;
            if digits[k] == b'9' {
                digits[k] = b'0';
            } else {
                digits[k] += 1;
                break;
            }
        }
        while end > start && digits[end - 1] == b'0' {
            end -= 1;
        }
    }
    lay_out(out, negative, &digits[start..end], point);
}

/// Appends the plain decimal of the `digits` with the point after `point` of them (before
/// them when not positive), `-` in front when `negative`.
fn lay_out(out: &mut Vec<u8>, negative: bool, digits: &[u8], point: i64) {
    if negative {
        out.push(b'-');
    }
    if point <= 0 {
        out.extend_from_slice(b"0.");
        out.resize(out.len() + point.unsigned_abs() as usize, b'0');
        out.extend_from_slice(digits);
    } else if point as usize >= digits.len() {
        out.extend_from_slice(digits);
        out.resize(out.len() + (point as usize - digits.len()), b'0');
    } else {
        let (whole, fraction) = digits.split_at(point as usize);
        out.extend_from_slice(whole);
        out.push(b'.');
        out.extend_from_slice(fraction);
    }
}

/// The exponent of the lowest set bit of `v` (not zero): `|v| = m 2^b` with `m` odd.
#[inline]
fn lowest_bit(v: f64) -> i64 {
    let bits = v.to_bits();
    let (exponent, fraction) = ((bits >> 52) & 0x7ff, bits & ((1 << 52) - 1));
    let (m, b) = match exponent {
        0 => (fraction, -1074i64),
        e => (fraction | (1 << 52), e as i64 - 1075),
    };
    b + i64::from(m.trailing_zeros())
}

/// True when `v` lies exactly halfway between the `digits` (a point after the first `point`
/// of them) and the next number of as many digits: `|v| = (10 D + 5) 10^q` with `D` the
/// digits as an integer and `q` one place below the last digit.
fn is_tie(v: f64, digits: &[u8], point: i64) -> bool {
    if digits.len() > 18 {
        return false;
    }
    let bits = v.to_bits();
    let (exponent, fraction) = ((bits >> 52) & 0x7ff, bits & ((1 << 52) - 1));
    let (mut m, mut b) = match exponent {
        0 => (fraction, -1074i64),
        e => (fraction | (1 << 52), e as i64 - 1075),
    };
    let zeros = m.trailing_zeros();
    m >>= zeros;
    b += i64::from(zeros);
    // |v| = m 2^b with m odd; the tie is T 10^q = T 5^q 2^q with T = 10 D + 5 odd.
    let q = point - digits.len() as i64 - 1;
    if b != q || q.unsigned_abs() > 55 {
        return false;
    }
    let d = digits
        .iter()
        .fold(0u128, |d, &c| d * 10 + u128::from(c - b'0'));
    let t = 10 * d + 5;
    let five = 5u128.pow(q.unsigned_abs() as u32);
    if q >= 0 {
        t.checked_mul(five) == Some(u128::from(m))
    } else {
        u128::from(m).checked_mul(five) == Some(t)
    }
}

/// The decimal exponent `ryu` writes after its `e` (`-7`, `20`).
fn exponent_of(text: &[u8]) -> i64 {
    let (sign, digits) = match text.split_first() {
        Some((b'-', rest)) => (-1, rest),
        _ => (1, text),
    };
    sign * digits
        .iter()
        .fold(0i64, |e, &d| e * 10 + i64::from(d - b'0'))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn shown(v: f64) -> String {
        let mut out = Vec::new();
        push(&mut out, v);
        String::from_utf8(out).unwrap()
    }

    fn debug_shown(v: f64) -> String {
        let mut out = b"x,".to_vec();
        push_debug(&mut out, v);
        String::from_utf8(out[2..].to_vec()).unwrap()
    }

    #[test]
    fn extremes_are_written_as_display_writes_them() {
        let values = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            0.30000000000000004,
            1e-7,
            1.5e-7,
            1e-4,
            0.00010000000000000002,
            9.999999999999999e-5,
            999_999_999_999_999.9,
            999_999_999_999_999.5,
            -0.1,
            -123.456,
            1e15,
            1e16,
            9_999_999_999_999_998.0,
            1e15 + 0.5,
            4096.0,
            1e20,
            123.456,
            125_406_270_313.0 + 33.0 / 64.0,
            -(125_406_270_313.0 + 33.0 / 64.0),
            9.5,
            0.25,
            (1u64 << 60) as f64,
            f64::MIN_POSITIVE,
            f64::MIN_POSITIVE / 3.0,
            f64::from_bits(1),
            -f64::from_bits(1),
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        for v in values {
            assert_eq!(shown(v), format!("{v}"), "{v:e}");
            assert_eq!(debug_shown(v), format!("{v:?}"), "{v:e}");
            assert_eq!(debug_shown(-v), format!("{:?}", -v), "{v:e}");
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]

        #[test]
        fn any_bits_are_written_as_display_writes_them(bits in any::<u64>()) {
            let v = f64::from_bits(bits);
            let text = shown(v);
            prop_assert_eq!(&text, &format!("{v}"));
            prop_assert_eq!(debug_shown(v), format!("{v:?}"));
            if v.is_finite() {
                // Read back bit for bit (negative zero included).
                prop_assert_eq!(text.parse::<f64>().unwrap().to_bits(), bits);
            }
        }

        #[test]
        fn subnormals_and_small_numbers_round_trip(mantissa in 1u64..(1 << 52), negative: bool) {
            let v = f64::from_bits(mantissa | (u64::from(negative) << 63));
            let text = shown(v);
            prop_assert_eq!(&text, &format!("{v}"));
            prop_assert_eq!(text.parse::<f64>().unwrap().to_bits(), v.to_bits());
        }

        #[test]
        fn short_binary_fractions_are_written_as_display_writes_them(
            m in 1u64..(1 << 53),
            shift in 0i32..80,
            up: bool,
        ) {
            // m 2^-shift or m 2^shift: exact ties between shortest candidates live here.
            let scale = 2f64.powi(if up { shift } else { -shift });
            let v = m as f64 * scale;
            prop_assert_eq!(shown(v), format!("{v}"));
            prop_assert_eq!(debug_shown(v), format!("{v:?}"));
        }

        #[test]
        fn ordinary_magnitudes_round_trip(v in -1e6f64..1e6) {
            prop_assert_eq!(shown(v), format!("{v}"));
            prop_assert_eq!(debug_shown(v), format!("{v:?}"));
        }
    }
}

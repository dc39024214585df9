//! The commonest number of a point file, a plain decimal (`-911.79784763606779`: a sign, digits,
//! a point and digits, at most 19 digits in all, no exponent), parsed to the nearest `f64`
//! faster than a general parser does it.
//!
//! Hand-written because the general parsers (`fast-float2`, `str::parse`) read most digits
//! one at a time and cover every form of a number; this reads the fraction eight digits at a
//! time and leaves every other form to them ([`parse_with`] answers `None`). The result is exact:
//! the digits make an integer `w < 10^19` and the value is `w / 10^m` with `10^m < 2^64`;
//! `w` shifted to 128 bits divided by `10^m` gives a quotient of at least 64 bits, and that
//! quotient with a sticky bit for a non-zero remainder converts (`u128 as f64`, round to
//! nearest, ties to even) to the correctly rounded significand, scaled exactly by a power
//! of two. Tests compare it with `str::parse` on random numbers.

/// The most digits (leading zeros included) a plain decimal has here: `10^19 - 1` fits `u64`.
const MAX_DIGITS: usize = 19;

/// The value of the plain decimal that `bytes` start with, its decimal mark `POINT` (`b'.'`,
/// or `b','` for a decimal comma), and its length in bytes; `None` when they start with
/// anything else (no digit before or after the mark, an exponent, more than 19 digits, a
/// point or comma right after the number, ...) or when fewer than eight bytes follow a run of
/// digits, for a general parser to read.
#[inline]
pub(crate) fn parse_with<const POINT: u8>(bytes: &[u8]) -> Option<(f64, usize)> {
    let (negative, mut k) = match bytes.first()? {
        b'-' => (true, 1),
        b'+' => (false, 1),
        _ => (false, 0),
    };
    let (mut w, int_digits) = digit_run(bytes, k)?;
    if int_digits == 0 || int_digits == 8 {
        return None;
    }
    k += int_digits;
    let mut frac_digits = 0;
    if bytes.get(k) == Some(&POINT) {
        k += 1;
        loop {
            let (run, n) = digit_run(bytes, k)?;
            if int_digits + frac_digits + n > MAX_DIGITS {
                return None;
            }
            w = w * POWERS_OF_TEN[n] + run;
            k += n;
            frac_digits += n;
            if n < 8 {
                break;
            }
        }
        if frac_digits == 0 {
            return None;
        }
    }
    if matches!(bytes.get(k), Some(b'e' | b'E' | b'.' | b'_')) || bytes.get(k) == Some(&POINT) {
        return None;
    }
    let magnitude = scaled(w, frac_digits);
    Some((if negative { -magnitude } else { magnitude }, k))
}

/// The number the digits at `bytes[k..]` write (at most eight of them) and how many there
/// are; `None` when fewer than eight bytes are left.
#[inline]
fn digit_run(bytes: &[u8], k: usize) -> Option<(u64, usize)> {
    let eight = <[u8; 8]>::try_from(bytes.get(k..k + 8)?).ok()?;
    let v = u64::from_le_bytes(eight);
    // The high bit of each byte that is not a digit; the lowest one is exact (the bytes
    // below it are digits, which neither carry nor borrow).
    let others = not_digits(v);
    let n = (others.trailing_zeros() / 8) as usize;
    Some(match n {
        0 => (0, 0),
        8 => (eight_digits(v), 8),
        // The n digits moved to the top, '0's below them.
        _ => (eight_digits((v << (8 * (8 - n))) | (ZEROS >> (8 * n))), n),
    })
}

/// `w / 10^m` correctly rounded, for `m <= 19`.
#[inline]
fn scaled(w: u64, m: usize) -> f64 {
    if m == 0 || w == 0 {
        // u64 to f64 rounds to nearest, ties to even.
        return w as f64;
    }
    let divisor = POWERS_OF_TEN[m];
    // 2^j <= divisor < 2^(j+1) and 2^(63+j) <= w·2^shift < 2^(64+j): the quotient is
    // above 2^62 and below 2^64.
    let j = 63 - divisor.leading_zeros();
    let shift = w.leading_zeros() + j;
    let numerator = u128::from(w) << shift;
    let divisor = u128::from(divisor);
    let quotient = numerator / divisor;
    let remainder = numerator - quotient * divisor;
    // Above 2^62, the quotient's lowest bit is far below the rounding position: setting it
    // for a non-zero remainder breaks a false tie and changes nothing else.
    let sticky = quotient as u64 | u64::from(remainder != 0);
    // Exact: 2^-shift is a normal f64 and so is the product (at least 2^-64).
    (sticky as f64) * f64::from_bits(u64::from(1023 - shift) << 52)
}

/// 10^0 ..= 10^19.
const POWERS_OF_TEN: [u64; 20] = {
    let mut powers = [1u64; 20];
    let mut k = 1;
    while k < 20 {
        powers[k] = powers[k - 1] * 10;
        k += 1;
    }
    powers
};

/// Eight ASCII '0's.
const ZEROS: u64 = 0x3030_3030_3030_3030;

/// The high bit of each byte of `v` that is not an ASCII digit, exact up to the lowest one.
#[inline]
fn not_digits(v: u64) -> u64 {
    let a = v.wrapping_add(0x4646_4646_4646_4646);
    let b = v.wrapping_sub(ZEROS);
    (a | b) & 0x8080_8080_8080_8080
}

/// The number that eight ASCII digits (little-endian in `v`, the first digit lowest) write.
#[inline]
fn eight_digits(mut v: u64) -> u64 {
    const MASK: u64 = 0x0000_00FF_0000_00FF;
    const MUL1: u64 = 0x000F_4240_0000_0064;
    const MUL2: u64 = 0x0000_2710_0000_0001;
    v -= 0x3030_3030_3030_3030;
    v = (v * 10) + (v >> 8);
    let v1 = (v & MASK).wrapping_mul(MUL1);
    let v2 = ((v >> 16) & MASK).wrapping_mul(MUL2);
    (v1.wrapping_add(v2) >> 32) as u32 as u64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plain decimal with a decimal point.
    fn parse(bytes: &[u8]) -> Option<(f64, usize)> {
        parse_with::<b'.'>(bytes)
    }

    /// `s` followed by a field separator and spaces, as in a file.
    fn padded(s: &str) -> Vec<u8> {
        format!("{s},        ").into_bytes()
    }

    /// Whether the plain parser read `s`, as the standard one does.
    fn same(s: &str) -> bool {
        let std = s.parse::<f64>().ok();
        match parse(&padded(s)) {
            Some((v, used)) => {
                assert_eq!(used, s.len(), "{s:?}");
                assert_eq!(
                    Some(v.to_bits()),
                    std.map(f64::to_bits),
                    "{s:?}: {v} vs {std:?}"
                );
                true
            }
            // Left to the general parser: nothing to compare.
            None => false,
        }
    }

    #[test]
    fn plain_decimals_are_read_and_others_left() {
        assert_eq!(
            parse(&padded("-911.79784763606779")),
            Some((-911.797_847_636_067_8, 19))
        );
        assert_eq!(parse(&padded("12")), Some((12.0, 2)));
        assert_eq!(parse(b"12"), None);
        assert_eq!(parse(b"+0.5\n       "), Some((0.5, 4)));
        assert_eq!(
            parse(&padded("-0.0")).map(|(v, _)| v.to_bits()),
            Some((-0.0f64).to_bits())
        );
        for other in [
            "",
            "-",
            "+",
            ".5",
            "5.",
            "1e5",
            "1.5E3",
            "1.2.3",
            "1_0",
            "x",
            "12345678901234567890",
            "0.12345678901234567890",
            "inf",
            "NaN",
        ] {
            assert_eq!(parse(&padded(other)), None, "{other:?}");
        }
        assert_eq!(parse_with::<b','>(b"-0,25;1        "), Some((-0.25, 5)));
        assert_eq!(parse_with::<b','>(b"0.25;1        "), None);
        assert_eq!(parse_with::<b','>(b"0,25,1        "), None);
        assert_eq!(eight_digits(u64::from_le_bytes(*b"12345678")), 12_345_678);
        assert_eq!(digit_run(b"1234567,", 0), Some((1_234_567, 7)));
        assert_eq!(digit_run(b"/1234567", 0), Some((0, 0)));
        assert_eq!(digit_run(b"12:45678", 0), Some((12, 2)));
        assert_eq!(digit_run(b"1234567", 0), None);
    }

    #[test]
    fn plain_decimals_round_as_the_standard_parser_does() {
        let mut state: u64 = 0x2545_f491_4f6c_dd1d;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut read = 0;
        for k in 0..400_000u64 {
            let digits = 1 + (next() % 19) as usize;
            let mut text: String = (0..digits)
                .map(|_| char::from(b'0' + (next() % 10) as u8))
                .collect();
            if k % 7 == 0 {
                // Long runs of nines and zeros: halfway and near-halfway cases.
                let run = (next() % digits as u64) as usize;
                let fill = if k % 2 == 0 { '9' } else { '0' };
                text.replace_range(digits - run.., &fill.to_string().repeat(run));
            }
            let point = (next() % (digits as u64 + 1)) as usize;
            if point > 0 && point < digits {
                text.insert(point, '.');
            }
            if k % 3 == 0 {
                text.insert(0, '-');
            }
            read += usize::from(same(&text));
        }
        assert!(read > 250_000, "{read}");
        // Values printed as a point file holds them: shortest, 17 digits, any precision.
        for _ in 0..200_000 {
            let unit = (next() >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            let v = unit * 10f64.powi((next() % 16) as i32 - 4);
            read += usize::from(same(&format!("{v}")));
            read += usize::from(same(&format!("{v:.17}")));
            read += usize::from(same(&format!("{:.*}", (next() % 20) as usize, v)));
        }
        assert!(read > 500_000, "{read}");
        // Exact ties between two doubles, and their neighbours (those of more than seven
        // integer digits are left to the general parser).
        for text in [
            "9007199254740993",
            "9007199254740995",
            "9007199254740993.00",
            "-9007199254740995.0",
            "18014398509481990",
            "18014398509481989.9",
            "18014398509481990.1",
            "0.30000000000000004",
            "0.1",
            "1.7976931348623157",
        ] {
            same(text);
        }
    }
}

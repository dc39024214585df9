//! NumPy's `.npy` format, version 1.0, for arrays of `f64`: the header of a C-order
//! little-endian (`'<f8'`) array of a given shape, and its values as bytes.
//!
//! The format (NumPy Enhancement Proposal 1, `numpy.lib.format`): the magic string
//! `\x93NUMPY`, the version bytes `1, 0`, the header's length as a little-endian `u16`, the
//! header itself — a Python dict literal `{'descr': '<f8', 'fortran_order': False, 'shape':
//! (N, 3), }` padded with spaces and ended by `\n` so that the data starts at a multiple of 64
//! bytes — and then the values, row-major. `np.load` reads it as is.
//!
//! Written by hand: only this one header, of one dtype, is ever written, and the values go out
//! block by block as they are sampled ([`crate::export::stream`]), which the crates for the
//! format (`npyz`, `ndarray-npy`) would do through their own writer types and a Python
//! literal parser for reading, dependencies and build time for twenty lines.

use std::io::Write;

use karkas::Point;

/// The header of an `.npy` file of `f64` values in C order with `shape`.
pub fn header(shape: &[usize]) -> Vec<u8> {
    let dims: Vec<String> = shape.iter().map(usize::to_string).collect();
    let shape = match dims.len() {
        1 => format!("({},)", dims[0]),
        _ => format!("({})", dims.join(", ")),
    };
    let mut dict = format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {shape}, }}");
    // Magic (6), version (2), length (2), the dict, spaces, '\n': a multiple of 64.
    let unpadded = 10 + dict.len() + 1;
    dict.extend(std::iter::repeat_n(
        ' ',
        unpadded.next_multiple_of(64) - unpadded,
    ));
    dict.push('\n');
    let mut out = Vec::with_capacity(10 + dict.len());
    out.extend_from_slice(b"\x93NUMPY\x01\x00");
    // The dict is a few dozen bytes whatever the shape (at most 20 digits per dimension).
    out.extend_from_slice(&(dict.len() as u16).to_le_bytes());
    out.extend_from_slice(dict.as_bytes());
    out
}

/// Appends `values` to `out` as little-endian `f64`.
pub fn push_values(out: &mut Vec<u8>, values: impl IntoIterator<Item = f64>) {
    for v in values {
        out.extend_from_slice(&v.to_le_bytes());
    }
}

/// Writes the coordinates of `points` to `out` as little-endian `f64`, point after point. On a
/// little-endian machine the points' memory is those bytes already and goes out as it is;
/// elsewhere the values go through `scratch`.
pub fn write_points<const D: usize>(
    out: &mut dyn Write,
    points: &[Point<D>],
    scratch: &mut Vec<u8>,
) -> std::io::Result<()> {
    if cfg!(target_endian = "little") {
        return out.write_all(bytemuck::cast_slice(points));
    }
    scratch.clear();
    push_values(scratch, points.iter().flat_map(|p| p.0));
    out.write_all(scratch)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_go_out_as_their_values_in_little_endian() {
        let points = [Point([1.5, -2.0, 1e-300]), Point([f64::MAX, 0.1, -0.0])];
        let mut written = Vec::new();
        write_points(&mut written, &points, &mut Vec::new()).unwrap();
        let mut expected = Vec::new();
        push_values(&mut expected, points.iter().flat_map(|p| p.0));
        assert_eq!(written, expected);
        assert_eq!(&written[..8], &1.5f64.to_le_bytes());
    }

    #[test]
    fn the_header_is_numpys() {
        let h = header(&[5, 3]);
        assert_eq!(h.len() % 64, 0);
        assert_eq!(&h[..8], b"\x93NUMPY\x01\x00");
        assert_eq!(u16::from_le_bytes([h[8], h[9]]) as usize, h.len() - 10);
        let dict = std::str::from_utf8(&h[10..]).unwrap();
        assert!(dict.starts_with("{'descr': '<f8', 'fortran_order': False, 'shape': (5, 3), }"));
        assert!(dict.ends_with(" \n"));
        let h = header(&[7]);
        assert!(std::str::from_utf8(&h[10..])
            .unwrap()
            .contains("'shape': (7,), }"));
        assert_eq!(header(&[usize::MAX, usize::MAX, 3]).len() % 64, 0);
    }
}

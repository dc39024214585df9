//! A triangle mesh as binary glTF 2.0 (`.glb`), the mesh format of the web and of game and
//! rendering engines (three.js, Blender, Windows 3D Viewer).
//!
//! The file is assembled by hand with `serde_json` for the JSON chunk: a `.glb` holding one
//! mesh is a 12-byte header, a JSON chunk (asset, one scene, one node, one mesh with one
//! triangle primitive, one material, three accessors, three buffer views, one buffer) and a
//! binary chunk. The `gltf-json` crate would only replace the `json!` literal below with typed
//! structs, at the price of its dependency tree.
//!
//! The seam of a closed sample grid is welded (see `mesh/shared_vertices.rs`).
//!
//! Binary chunk: positions (`f32` VEC3, with the `min`/`max` glTF requires), normals (`f32`
//! VEC3, unit length, from the mesh or averaged over the faces) and indices (`u32` SCALAR).
//! glTF is `f32` by definition, so coordinates lose precision beyond 7 digits; the mesh is
//! placed as it is (no recentring).

use std::io::{self, Write};
use std::path::Path;

use serde_json::json;

use crate::error::IoError;
use crate::mesh::error::MeshError;
use crate::mesh::shared_vertices::SharedVertices;
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::write::write_atomic;

/// Writes `mesh` as binary glTF at `path`, atomically. A mesh failing
/// [`TriangleMesh::validate`] or too large for 32-bit glTF lengths
/// ([`MeshError::TooLargeForGltf`]) is an [`IoError::InvalidMesh`], nothing written.
pub fn write_mesh_glb(path: &Path, mesh: &TriangleMesh) -> Result<(), IoError> {
    mesh.check_writable(path)?;
    buffer_lengths(&SharedVertices::of(mesh)).map_err(IoError::invalid_mesh(path))?;
    write_atomic(path, |out| render_mesh_glb(mesh, out))
}

/// The byte lengths of the vertex and index buffers of `mesh` and of the whole binary chunk;
/// [`MeshError::TooLargeForGltf`] when they overflow.
fn buffer_lengths(mesh: &SharedVertices) -> Result<(usize, usize, usize), MeshError> {
    let vertex_bytes = mesh.vertex_count().checked_mul(12);
    let index_bytes = mesh.triangle_count().checked_mul(12);
    let (Some(vertex_bytes), Some(index_bytes)) = (vertex_bytes, index_bytes) else {
        return Err(MeshError::TooLargeForGltf);
    };
    let bin_len = vertex_bytes
        .checked_mul(2)
        .and_then(|v| v.checked_add(index_bytes))
        .ok_or(MeshError::TooLargeForGltf)?;
    Ok((vertex_bytes, index_bytes, bin_len))
}

/// Writes the `.glb` bytes of `mesh` into `out` (the mesh is assumed valid; one too large for
/// glTF is [`io::ErrorKind::InvalidInput`] carrying [`MeshError::TooLargeForGltf`]).
pub fn render_mesh_glb(mesh: &TriangleMesh, out: &mut dyn Write) -> io::Result<()> {
    let mesh = SharedVertices::of(mesh);
    let n = mesh.vertex_count();
    let m = mesh.triangle_count();
    let too_large = || io::Error::new(io::ErrorKind::InvalidInput, MeshError::TooLargeForGltf);
    let (vertex_bytes, index_bytes, bin_len) = buffer_lengths(&mesh).map_err(|_| too_large())?;
    let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
    for p in mesh.positions() {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c] as f32);
            hi[c] = hi[c].max(p[c] as f32);
        }
    }
    if n == 0 {
        (lo, hi) = ([0.0; 3], [0.0; 3]);
    }
    let document = json!({
        "asset": {"version": "2.0", "generator": "karkas"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "karkas surface"}],
        "meshes": [{"primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1},
            "indices": 2,
            "material": 0,
            "mode": 4
        }]}],
        "materials": [{
            "pbrMetallicRoughness": {
                "baseColorFactor": [0.72, 0.78, 0.88, 1.0],
                "metallicFactor": 0.0,
                "roughnessFactor": 0.6
            },
            "doubleSided": true
        }],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3",
             "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5125, "count": 3 * m, "type": "SCALAR"}
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": vertex_bytes, "target": 34962},
            {"buffer": 0, "byteOffset": vertex_bytes, "byteLength": vertex_bytes, "target": 34962},
            {"buffer": 0, "byteOffset": 2 * vertex_bytes, "byteLength": index_bytes, "target": 34963}
        ],
        "buffers": [{"byteLength": bin_len}]
    });
    let mut json_bytes = serde_json::to_vec(&document).map_err(io::Error::other)?;
    while json_bytes.len() % 4 != 0 {
        json_bytes.push(b' ');
    }
    // bin_len is a multiple of 4 (every item is 4 bytes wide).
    let total = 12 + 8 + json_bytes.len() + 8 + bin_len;
    let total = u32::try_from(total).map_err(|_| too_large())?;
    out.write_all(b"glTF")?;
    out.write_all(&2u32.to_le_bytes())?;
    out.write_all(&total.to_le_bytes())?;
    out.write_all(&(json_bytes.len() as u32).to_le_bytes())?;
    out.write_all(b"JSON")?;
    out.write_all(&json_bytes)?;
    out.write_all(&(bin_len as u32).to_le_bytes())?;
    out.write_all(b"BIN\0")?;
    for p in mesh.positions() {
        for c in 0..3 {
            out.write_all(&(p[c] as f32).to_le_bytes())?;
        }
    }
    for p in mesh.normals() {
        for c in 0..3 {
            out.write_all(&(p[c] as f32).to_le_bytes())?;
        }
    }
    for t in mesh.triangles() {
        for k in t {
            out.write_all(&k.to_le_bytes())?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::{Grid, Point3};

    /// The container structure of a 3 x 2 grid: header, chunk lengths and types, and the
    /// accessor counts in the JSON.
    #[test]
    fn container_structure() {
        let grid = Grid::from_fn(3, 2, |a, b| Point3::new([a as f64, b as f64, -1.0]));
        let mesh = TriangleMesh::from_grid(&grid).unwrap();
        let mut out = Vec::new();
        render_mesh_glb(&mesh, &mut out).unwrap();
        let u32_at = |k: usize| u32::from_le_bytes(out[k..k + 4].try_into().unwrap()) as usize;
        assert_eq!(&out[0..4], b"glTF");
        assert_eq!(u32_at(4), 2);
        assert_eq!(u32_at(8), out.len());
        let json_len = u32_at(12);
        assert_eq!(json_len % 4, 0);
        assert_eq!(&out[16..20], b"JSON");
        let doc: serde_json::Value = serde_json::from_slice(&out[20..20 + json_len]).unwrap();
        let bin_at = 20 + json_len;
        assert_eq!(&out[bin_at + 4..bin_at + 8], b"BIN\0");
        assert_eq!(u32_at(bin_at), 2 * 6 * 12 + 4 * 12);
        assert_eq!(out.len(), bin_at + 8 + u32_at(bin_at));
        assert_eq!(doc["accessors"][0]["count"], 6);
        assert_eq!(doc["accessors"][2]["count"], 12);
        assert_eq!(doc["accessors"][0]["min"], json!([0.0, 0.0, -1.0]));
        assert_eq!(doc["accessors"][0]["max"], json!([2.0, 1.0, -1.0]));
        // The last index of the binary chunk is the last corner of the last triangle.
        assert_eq!(u32_at(out.len() - 4), mesh.triangles[3][2] as usize);
    }
}

//! What can be wrong with a triangle mesh or a sample grid handed to a mesh writer, or with a
//! mesh read from a file: the checks of `TriangleMesh::validate` and the grid and size limits
//! of the formats.

/// Why a mesh (or a sample grid) cannot be written, or why a mesh read from a file is unusable.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum MeshError {
    /// Normals are given, but not one per vertex.
    #[error("{normals} normals for {vertices} vertices")]
    NormalCount {
        /// The number of normals.
        normals: usize,
        /// The number of vertices.
        vertices: usize,
    },
    /// More vertices than 32-bit mesh indices can address.
    #[error("{vertices} vertices are more than 32-bit mesh indices can address")]
    TooManyVertices {
        /// The number of vertices asked for.
        vertices: usize,
    },
    /// A triangle names a vertex that does not exist.
    #[error("triangle {triangle} has vertex index {corners:?} out of range (0..{vertices})")]
    IndexOutOfRange {
        /// The 0-based number of the triangle.
        triangle: usize,
        /// Its three vertex indices.
        corners: [u32; 3],
        /// The number of vertices.
        vertices: usize,
    },
    /// The grid shape of the mesh does not match its vertex count.
    #[error("{vertices} vertices do not form a {rows} x {cols} grid")]
    GridShape {
        /// The number of vertices.
        vertices: usize,
        /// The rows of the grid shape.
        rows: usize,
        /// The columns of the grid shape.
        cols: usize,
    },
    /// A sample grid handed over as a flat list has the wrong number of points.
    #[error("{points} points do not form a {rows} x {cols} grid")]
    PointCount {
        /// The number of points.
        points: usize,
        /// The rows asked for.
        rows: usize,
        /// The columns asked for.
        cols: usize,
    },
    /// More triangles than binary STL can count (its count is 32-bit).
    #[error("{triangles} triangles are more than binary STL can hold")]
    TooManyTriangles {
        /// The number of triangles.
        triangles: usize,
    },
    /// A general triangle mesh asked to be written as a structured grid (`.vts`).
    #[error(
        "a .vts structured grid needs a sampled surface grid, not a general triangle mesh (use .vtk)"
    )]
    NotStructured,
    /// A mesh whose buffers exceed the 32-bit lengths of glTF.
    #[error("mesh too large for glTF")]
    TooLargeForGltf,
}

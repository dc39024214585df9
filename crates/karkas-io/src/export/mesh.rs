//! A triangle mesh in a mesh format or as the 3-D viewer page.

use super::formats::MESH_FORMATS;
use crate::mesh::{write_mesh_as, MeshOptions, TriangleMesh};
use crate::viewer::{write_viewer_html, ViewerMesh, ViewerScene};
use crate::{IoError, OutputFormat};
use std::path::Path;

/// Writes `mesh` at `output` in `format`, one of [`MESH_FORMATS`] (turned over first when
/// `options` say so): a mesh format, or the viewer page titled `title`.
pub fn write_triangle_mesh(
    output: &Path,
    format: OutputFormat,
    mut mesh: TriangleMesh,
    options: &MeshOptions,
    title: &str,
) -> Result<(), IoError> {
    let format = format.allowed_for(output, &MESH_FORMATS)?;
    if options.flip_normals {
        mesh.flip_orientation();
    }
    if format == OutputFormat::Html {
        let scene = ViewerScene {
            title: title.to_owned(),
            meshes: vec![ViewerMesh {
                name: title.to_owned(),
                mesh,
            }],
            ..ViewerScene::default()
        };
        return write_viewer_html(output, &scene);
    }
    let options = MeshOptions {
        flip_normals: false,
        ..*options
    };
    write_mesh_as(format, output, &mesh, &options)
}

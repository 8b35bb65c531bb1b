/**
 * A scene onto the engine: {@link studio.server.scene.compiling.SceneCompiler} reads it and
 * {@link studio.server.scene.compiling.SceneMapper} maps each part onto its engine type (filling in
 * defaults, checking the server's limits and the rules that span fields), reading meshes from
 * {@link studio.server.scene.compiling.MeshFiles} through the {@link studio.server.scene.compiling.MeshCache}.
 * The result, a {@link studio.server.scene.compiling.CompiledScene}, is what the render, job, live
 * view and command line features render. Depends on the format and reading.
 */
package studio.server.scene.compiling;

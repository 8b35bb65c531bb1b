/**
 * The example scenes and meshes shipped in the jar (copied from the repository's scenes/ folder),
 * served to the editor: GET /api/scenes, /api/scenes/{name} and /api/meshes?file=.
 */
package studio.server.scene.examples;

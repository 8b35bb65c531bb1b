/**
 * glTF 2.0 models read into the engine's meshes and materials: {@link studio.server.scene.gltf.GltfReader}
 * takes a .glb or a .gltf, walks its default scene's node hierarchy, reads its triangle primitives and
 * maps its materials onto the six of the scene format, and lists everything it does not draw as
 * warnings ({@link studio.server.scene.gltf.GltfModel}).
 *
 * <p>Read with Jackson, which the server already uses, rather than with JglTF: that library would
 * bring a second Jackson (2.x, beside the server's 3.x), it resolves a buffer's relative URI as a
 * file to read, and it allocates what an accessor declares; an upload is untrusted, so every count,
 * offset, stride and index here is checked against the bytes that are really there before anything
 * is allocated, and nothing outside the file is read but other assets named by id.
 */
package studio.server.scene.gltf;

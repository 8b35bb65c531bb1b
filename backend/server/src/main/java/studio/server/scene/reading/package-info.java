/**
 * Scene JSON in, a validated {@link studio.server.scene.format.SceneDto} out:
 * {@link studio.server.scene.reading.SceneReader} reads strictly and validates, a fast path binds
 * plainly valid scenes without Jackson's binding and the validator, and a malformed body is
 * reported by its JSON path in the user's words. Depends on the format only.
 */
package studio.server.scene.reading;

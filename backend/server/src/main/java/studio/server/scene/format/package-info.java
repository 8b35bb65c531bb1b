/**
 * The scene format: the records a scene file binds to ({@link studio.server.scene.format.SceneDto}
 * and its parts) with their Bean Validation rules, the defaults of every field left out, the
 * server's configurable limits, the JSON Schema published from the records (GET /api/scene-schema),
 * and what a broken rule is ({@link studio.server.scene.format.InvalidSceneException}: a 400 naming
 * each field by its JSON path). It depends on no other part of the server.
 */
package studio.server.scene.format;

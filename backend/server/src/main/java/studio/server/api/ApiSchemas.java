package studio.server.api;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import studio.server.scene.format.SceneLimits;
import studio.server.scene.format.SceneSchema;

/**
 * The schemas of the OpenAPI document, as JSON Schema 2020-12 maps: the scene format from
 * {@link SceneSchema} (its root as {@code Scene}, each of its {@code $defs} beside it), the problem
 * bodies and a job's status.
 */
final class ApiSchemas {

    static final String REF = "#/components/schemas/";

    static final String PROBLEM = """
            {
              "type": "object",
              "description": "An RFC 9457 problem (application/problem+json).",
              "properties": {
                "type": { "type": "string" },
                "title": { "type": "string" },
                "status": { "type": "integer", "minimum": 400, "maximum": 599 },
                "detail": { "type": "string" },
                "instance": { "type": "string" }
              },
              "required": ["title", "status"]
            }""";

    static final String FIELD_ERROR = """
            {
              "type": "object",
              "description": "One thing wrong with a scene.",
              "properties": {
                "field": { "type": "string",
                  "description": "The field's JSON path, such as objects[2].radius; empty for the body as a whole." },
                "message": { "type": "string", "minLength": 1 }
              },
              "required": ["field", "message"],
              "additionalProperties": false
            }""";

    static final String INVALID_SCENE_PROBLEM = """
            {
              "description": "A problem listing each bad field of the scene by its JSON path; nothing was rendered.",
              "allOf": [
                { "$ref": "#/components/schemas/Problem" },
                {
                  "type": "object",
                  "properties": {
                    "status": { "const": 400 },
                    "errors": { "type": "array", "minItems": 1, "items": { "$ref": "#/components/schemas/FieldError" } }
                  },
                  "required": ["errors"]
                }
              ]
            }""";

    static final String JOB_STATUS = """
            {
              "type": "object",
              "description": "A render job as the API shows it.",
              "properties": {
                "id": { "type": "string" },
                "state": { "type": "string", "enum": ["queued", "running", "done", "failed", "cancelled"] },
                "progress": { "type": "number", "minimum": 0, "maximum": 1, "description": "finished tiles / all tiles" },
                "elapsedMillis": { "type": "integer", "minimum": 0 },
                "raysPerSecond": { "type": ["number", "null"], "description": "when done, else null" },
                "width": { "type": "integer", "minimum": 1 },
                "height": { "type": "integer", "minimum": 1 },
                "fileName": { "type": "string" },
                "mediaType": { "type": "string", "enum": ["image/png", "image/jpeg"] },
                "error": { "type": ["string", "null"], "description": "why it failed or was cancelled, else null" },
                "workers": { "type": "object", "additionalProperties": { "type": "integer", "minimum": 0 },
                             "description": "in a cluster: the tiles each member (host:port) rendered; absent in a cluster of one" }
              },
              "required": ["id", "state", "progress", "elapsedMillis", "raysPerSecond", "width", "height",
                           "fileName", "mediaType", "error"],
              "additionalProperties": false
            }""";

    static final String TILE_EVENT = """
            {
              "type": "object",
              "description": "A finished tile: its rectangle in the image and its pixels as a base64 PNG.",
              "properties": {
                "x": { "type": "integer", "minimum": 0 },
                "y": { "type": "integer", "minimum": 0 },
                "width": { "type": "integer", "minimum": 1 },
                "height": { "type": "integer", "minimum": 1 },
                "png": { "type": "string", "contentEncoding": "base64", "contentMediaType": "image/png" },
                "progress": { "type": "number", "minimum": 0, "maximum": 1 }
              },
              "required": ["x", "y", "width", "height", "png", "progress"],
              "additionalProperties": false
            }""";

    /** One server-sent event of a job's stream, as event-stream readers (and OpenAPI 3.2's itemSchema) see it. */
    static final String JOB_EVENT = """
            {
              "type": "object",
              "properties": {
                "event": { "enum": ["status", "tile", "end"] },
                "data": { "type": "string", "contentMediaType": "application/json" },
                "id": { "type": "string" },
                "retry": { "type": "integer" }
              },
              "required": ["event", "data"],
              "oneOf": [
                { "properties": { "event": { "enum": ["status", "end"] },
                                  "data": { "contentSchema": { "$ref": "#/components/schemas/JobStatus" } } } },
                { "properties": { "event": { "const": "tile" },
                                  "data": { "contentSchema": { "$ref": "#/components/schemas/TileEvent" } } } }
              ]
            }""";

    /** A small scene, the request bodies' example: it renders in milliseconds. */
    static final String EXAMPLE_SCENE = """
            {
              "name": "example",
              "image": { "width": 64, "height": 48 },
              "camera": { "position": [0, 1.5, 5], "lookAt": [0, 0.8, 0] },
              "render": { "samples": 4, "maxDepth": 4 },
              "lights": [ { "type": "point", "position": [5, 8, 5] } ],
              "objects": [
                { "type": "sphere", "material": { "type": "plastic", "color": "#cc3333" } },
                { "type": "plane" }
              ]
            }""";

    static final String SCENE_SUMMARY = """
            {
              "type": "object",
              "description": "One example scene, by its file stem.",
              "properties": { "name": { "type": "string" } },
              "required": ["name"],
              "additionalProperties": false
            }""";

    static final String HEALTH = """
            {
              "type": "object",
              "properties": {
                "status": { "type": "string", "enum": ["UP", "DOWN", "OUT_OF_SERVICE", "UNKNOWN"] },
                "components": {
                  "type": "object",
                  "description": "Each check's status, and its details for a signed-in caller only (none with sign-in off); renderMemory: the memory budget's capacityBytes, reservedBytes and freeBytes",
                  "additionalProperties": {
                    "type": "object",
                    "properties": { "status": { "type": "string" }, "details": { "type": "object" } }
                  }
                }
              },
              "required": ["status"]
            }""";

    static final String ME = """
            {
              "type": "object",
              "description": "The caller, as the server knows them.",
              "properties": {
                "principal": { "type": "string", "description": "The API key's name or the token's sub; empty with sign-in off" },
                "signInRequired": { "type": "boolean", "description": "Whether this server asks every caller to sign in" }
              },
              "required": ["principal", "signInRequired"],
              "additionalProperties": false
            }""";

    static final String PREVIEW_TICKET = """
            {
              "type": "object",
              "description": "A single-use ticket for the live view: open /api/preview?ticket=TICKET within expiresInSeconds.",
              "properties": {
                "ticket": { "type": "string", "pattern": "^[A-Za-z0-9_-]{43}$" },
                "expiresInSeconds": { "type": "integer", "minimum": 1 }
              },
              "required": ["ticket", "expiresInSeconds"],
              "additionalProperties": false
            }""";

    private ApiSchemas() {
    }

    /**
     * The scene format with this server's limits, as components: {@code Scene} and its definitions
     * ({@code Object}, {@code SphereObject}, {@code Material}, ...), with every {@code $ref} to
     * {@code #/$defs/X} rewritten to {@code #/components/schemas/X}.
     */
    @SuppressWarnings("unchecked")
    static Map<String, Object> sceneComponents(SceneLimits limits) {
        Map<String, Object> root = new LinkedHashMap<>(SceneSchema.of(limits));
        root.remove("$schema");
        Map<String, Object> defs = (Map<String, Object>) root.remove("$defs");
        Map<String, Object> components = new LinkedHashMap<>();
        components.put("Scene", rewriteRefs(root));
        defs.forEach((name, def) -> {
            if (components.containsKey(name)) {
                throw new IllegalStateException("the scene schema defines " + name + " twice");
            }
            components.put(name, rewriteRefs(def));
        });
        return components;
    }

    @SuppressWarnings("unchecked")
    private static Object rewriteRefs(Object node) {
        if (node instanceof Map<?, ?> map) {
            Map<String, Object> copy = new LinkedHashMap<>();
            ((Map<String, Object>) map).forEach((key, value) -> copy.put(key,
                    key.equals("$ref") ? ((String) value).replace("#/$defs/", REF) : rewriteRefs(value)));
            return copy;
        }
        if (node instanceof List<?> list) {
            return list.stream().map(ApiSchemas::rewriteRefs).toList();
        }
        return node;
    }
}

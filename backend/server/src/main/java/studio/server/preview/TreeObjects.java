package studio.server.preview;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.function.Function;

import studio.engine.geometry.Shape;
import studio.engine.geometry.TriangleMesh;
import studio.engine.memory.MemoryGate;
import studio.engine.scene.SceneObject;
import studio.server.scene.compiling.CompiledScene;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.JsonNodeFactory;
import tools.jackson.databind.node.ObjectNode;

/**
 * A patched scene, a Jackson tree, as the bytes a scene is read from: whole, with one of its
 * objects alone, or with a stand-in object (to read all of it but the objects).
 */
final class TreeObjects {

    /** The members of a mesh that name its triangles. */
    private static final String[] SOURCES = {"obj", "file", "asset"};
    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final JsonNode SPHERE = JsonNodeFactory.instance.objectNode().put("type", "sphere");

    private TreeObjects() {
    }

    static byte[] bytes(JsonNode scene) {
        return JSON.writeValueAsBytes(scene);
    }

    /** The scene with a default sphere for its objects: how its camera, lights and settings read. */
    static byte[] frame(JsonNode scene) {
        return alone(scene, SPHERE);
    }

    /**
     * Object {@code i} of {@code scene} read alone (see {@link ObjectReading}); a mesh whose source
     * ({@code obj}, {@code file} or {@code asset}) is that of {@code before}, the element {@code kept}
     * was read from, is read with a stand-in source and the kept mesh moved. Null: read the whole scene.
     */
    static SceneObject read(JsonNode scene, int i, JsonNode before, Shape kept, MemoryGate memory,
                            Function<byte[], CompiledScene> read) {
        JsonNode element = scene.get("objects").get(i);
        if (kept instanceof TriangleMesh mesh && element.isObject() && before != null && sameSource(before, element)) {
            Map<String, JsonNode> members = new LinkedHashMap<>();
            element.properties().forEach(e -> members.put(e.getKey(), e.getValue()));
            for (String source : SOURCES) {
                members.remove(source);
            }
            members.put("obj", JsonNodeFactory.instance.stringNode(ObjectReading.STAND_IN));
            ObjectNode standIn = new ObjectNode(JsonNodeFactory.instance, members);
            return ObjectReading.movedMesh(mesh, alone(scene, standIn), memory, read);
        }
        return ObjectReading.alone(alone(scene, element), read);
    }

    /** The element at {@code i} of a scene's objects, or null. */
    static JsonNode element(JsonNode scene, int i) {
        JsonNode objects = scene != null ? scene.get("objects") : null;
        return objects != null && objects.isArray() && i < objects.size() ? objects.get(i) : null;
    }

    private static boolean sameSource(JsonNode before, JsonNode after) {
        boolean any = false;
        for (String source : SOURCES) {
            JsonNode was = before.get(source), is = after.get(source);
            if (was != is && !Objects.equals(was, is)) {
                return false;
            }
            any |= is != null;
        }
        return any;
    }

    private static byte[] alone(JsonNode scene, JsonNode element) {
        Map<String, JsonNode> members = new LinkedHashMap<>();
        scene.properties().forEach(e -> members.put(e.getKey(), e.getValue()));
        ArrayNode one = JsonNodeFactory.instance.arrayNode();
        one.add(element);
        members.put("objects", one);
        return bytes(new ObjectNode(JsonNodeFactory.instance, members));
    }
}

package studio.server.scene.gltf;

import static studio.server.scene.gltf.GltfJson.bad;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Set;

import tools.jackson.databind.JsonNode;

import studio.engine.math.Affine;
import studio.engine.math.Vec3;

/**
 * The default scene's node hierarchy ({@code scene}, or the first of {@code scenes}), walked from its
 * roots: each node's transform (a column-major {@code matrix}, or {@code translation}, {@code rotation}
 * as a unit quaternion and {@code scale}, composed T * R * S) after its parent's. Nodes form trees: a
 * node reached twice (two parents, or a cycle) is refused, so the walk visits each node at most once
 * and a file's instances are never more than its nodes. Iterative, so a deep chain cannot overflow the
 * stack.
 */
final class GltfNodes {

    /** A mesh placed by a node: the mesh's index and the map from its space to the model's. */
    record Instance(int mesh, Affine modelFromMesh, String node) {
    }

    /** A node still to visit, and its parent's transform. */
    private record Pending(int node, Affine parent) {
    }

    private GltfNodes() {
    }

    static List<Instance> walk(JsonNode root, Set<String> warnings) {
        JsonNode scenes = GltfJson.array(root, "scenes", "");
        JsonNode nodes = GltfJson.array(root, "nodes", "");
        int meshes = GltfJson.array(root, "meshes", "").size();
        if (scenes.isEmpty()) {
            throw bad("scenes", "the file has no scene to draw");
        }
        int scene = GltfJson.optionalIndex(root, "scene", scenes.size(), "scenes", "");
        if (scenes.size() > 1) {
            warnings.add("only the default scene (scenes[" + Math.max(scene, 0) + "]) is drawn, not the file's other "
                    + (scenes.size() - 1));
        }
        String scenePath = "scenes[" + Math.max(scene, 0) + "]";
        JsonNode roots = GltfJson.array(GltfJson.element(scenes, Math.max(scene, 0), "scenes"), "nodes", scenePath + ".");
        boolean[] reached = new boolean[nodes.size()];
        List<Instance> instances = new ArrayList<>();
        Deque<Pending> todo = new ArrayDeque<>();
        for (int r = roots.size() - 1; r >= 0; r--) {
            todo.push(new Pending(nodeIndex(roots.get(r), nodes.size(), scenePath + ".nodes[" + r + "]"),
                    Affine.IDENTITY));
        }
        while (!todo.isEmpty()) {
            Pending next = todo.pop();
            int i = next.node();
            String path = "nodes[" + i + "]";
            if (reached[i]) {
                throw bad(path, "is reached twice; a node has at most one parent, and nodes form no cycle");
            }
            reached[i] = true;
            JsonNode node = GltfJson.element(nodes, i, "nodes");
            Affine transform = next.parent().times(local(node, path));
            noted(node, path, warnings);
            int mesh = GltfJson.optionalIndex(node, "mesh", meshes, "meshes", path);
            if (mesh >= 0) {
                instances.add(new Instance(mesh, transform, path));
            }
            JsonNode children = GltfJson.array(node, "children", path + ".");
            for (int c = children.size() - 1; c >= 0; c--) {
                todo.push(new Pending(nodeIndex(children.get(c), nodes.size(), path + ".children[" + c + "]"),
                        transform));
            }
        }
        return instances;
    }

    private static int nodeIndex(JsonNode value, int size, String path) {
        if (value == null || !value.isIntegralNumber() || !value.canConvertToInt() || value.intValue() < 0
                || value.intValue() >= size) {
            throw bad(path, "must name one of the " + size + " nodes");
        }
        return value.intValue();
    }

    /** A node's own transform: its matrix, or its translation, rotation and scale. */
    private static Affine local(JsonNode node, String path) {
        double[] matrix = GltfJson.numbers(node, "matrix", 16, null, path);
        if (matrix != null) {
            try {
                return Affine.fromColumnMajor(matrix);
            } catch (IllegalArgumentException e) {
                throw bad(path + ".matrix", e.getMessage());
            }
        }
        double[] t = GltfJson.numbers(node, "translation", 3, new double[] {0, 0, 0}, path);
        double[] r = GltfJson.numbers(node, "rotation", 4, new double[] {0, 0, 0, 1}, path);
        double[] s = GltfJson.numbers(node, "scale", 3, new double[] {1, 1, 1}, path);
        try {
            return Affine.trs(new Vec3(t[0], t[1], t[2]), r[0], r[1], r[2], r[3], new Vec3(s[0], s[1], s[2]));
        } catch (IllegalArgumentException e) {
            throw bad(path + ".rotation", e.getMessage());
        }
    }

    /** What a node has that is not drawn. */
    private static void noted(JsonNode node, String path, Set<String> warnings) {
        if (!node.path("camera").isMissingNode()) {
            warnings.add(path + ": cameras are not used (the scene's camera is)");
        }
        if (!node.path("skin").isMissingNode()) {
            warnings.add(path + ": skins are not applied; the mesh is drawn in its bind pose");
        }
        if (!node.path("weights").isMissingNode()) {
            warnings.add(path + ": morph target weights are not applied");
        }
        for (String extension : node.path("extensions").propertyNames()) {
            warnings.add(path + ": the extension " + extension + " is not drawn");
        }
    }
}

package studio.server.scene.compiling;

import static studio.server.scene.compiling.FormatValues.or;
import static studio.server.scene.compiling.FormatValues.vec;

import java.util.ArrayList;
import java.util.List;

import studio.engine.geometry.TriangleMesh;
import studio.engine.memory.MemoryGate;
import studio.engine.material.Material;
import studio.engine.scene.SceneObject;
import studio.engine.texture.ImageTexture;
import studio.engine.texture.MipMap;
import studio.server.scene.gltf.GltfModel;
import studio.server.scene.gltf.GltfPart;
import studio.server.scene.gltf.GltfReader;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.SceneDefaults;

/**
 * The glTF models of one scene: each one's file or asset read ({@link GltfReader}) or taken from the
 * {@link MeshCache}, within the triangles the scene may still have, and each of its parts (one per
 * material) placed as a mesh is, as a scene object of its own. Reads assets through the same
 * {@link MeshAssets} as meshes do, so on a cluster member the model, and the buffers and images it
 * names by id, come from the cluster's store.
 *
 * <p>The parts' base colour textures and TEXCOORD_0 are read into the model; the engine has no
 * textured material yet, so they are not attached here (the upload's warnings say so).
 */
final class GltfMapping {

    private final TriangleBudget budget;
    private final MeshCache cache;
    /** Decoded base colour textures, by the model's digest and the part's index. */
    private final TextureCache textures;
    private final MeshFiles files;
    private final MeshAssets assets;
    private final MemoryGate memory;
    private final MappingProblems problems;

    GltfMapping(TriangleBudget budget, MeshCache cache, TextureCache textures, MeshFiles files, MeshAssets assets,
                MemoryGate memory, MappingProblems problems) {
        this.budget = budget;
        this.cache = cache;
        this.textures = textures;
        this.files = files;
        this.assets = assets;
        this.memory = memory;
        this.problems = problems;
    }

    /** The model's parts placed in the scene; none (and a problem) if it cannot be. */
    List<SceneObject> of(ObjectDto.Gltf gltf, String path) {
        if ((gltf.file() == null) == (gltf.asset() == null)) {
            problems.add(path, gltf.file() == null ? "a glTF model needs a \"file\" name or an \"asset\" id"
                    : "give the glTF model one of \"file\" and \"asset\", not both");
            return List.of();
        }
        String field = path + (gltf.asset() != null ? ".asset" : ".file");
        byte[] bytes = problems.attempt(field, () -> gltf.asset() != null ? assets.gltf(gltf.asset())
                : files.gltf(gltf.file()));
        if (bytes == null) {
            if (!problems.has(field)) {
                problems.add(field, "this server has no asset " + gltf.asset() + "; upload it (POST /api/assets) "
                        + "and send the scene again");
            }
            return List.of();
        }
        String digest = gltf.asset() != null ? cache.keyOfAsset(gltf.asset()) : cache.keyOf(bytes);
        GltfModel model = model(bytes, digest, field);
        if (model == null) {
            return List.of();
        }
        budget.spend(model.triangleCount());
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < model.parts().size(); i++) {
            GltfPart part = model.parts().get(i);
            MeshCache.Placement placement = new MeshCache.Placement(digest == null ? null : digest + "#" + i,
                    vec(or(gltf.position(), SceneDefaults.ORIGIN)), or(gltf.scale(), SceneDefaults.MESH_SCALE),
                    vec(or(gltf.rotation(), SceneDefaults.ORIGIN)));
            TriangleMesh shape = digest == null ? null : cache.built(placement);
            if (shape == null) {
                TriangleMesh elsewhere = digest == null ? null : cache.sameShape(placement);
                shape = problems.attempt(field, () -> elsewhere != null
                        ? elsewhere.movedTo(placement.position(), memory)
                        : new TriangleMesh(part.mesh(), placement.position(), placement.scale(), placement.rotation(),
                                memory));
                if (shape == null) {
                    return List.of();
                }
                cache.keepBuilt(placement, shape);
            }
            Material material = textured(part, digest == null ? null : digest + "#" + i, field);
            if (material == null) {
                return List.of();
            }
            objects.add(new SceneObject(shape, material));
        }
        return objects;
    }

    /**
     * The part's material, its base colour texture decoded (once per model and part, then kept) where
     * it has one and UVs to lay it on; null (and a problem) if the image cannot be read.
     */
    private Material textured(GltfPart part, String key, String field) {
        if (part.texture() == null || part.mesh().uvs() == null) {
            return part.material();
        }
        MipMap image = key == null ? null : textures.get(key);
        if (image == null) {
            image = problems.attempt(field, () -> {
                try {
                    return TextureMapping.decode(part.texture().image(), memory);
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException(part.texture().source() + " " + e.getMessage());
                }
            });
            if (image == null) {
                return null;
            }
            textures.keep(key, image);
        }
        return part.material().withTexture(new ImageTexture(image));
    }

    /** The model of the file's bytes (read before, or now and kept); null (and a problem) if it cannot be read. */
    private GltfModel model(byte[] bytes, String digest, String field) {
        GltfModel model = digest != null ? cache.model(digest) : null;
        if (model == null) {
            int left = Math.max(0, budget.left());
            try {
                model = GltfReader.read(bytes, id -> assets.bytes(id), left, memory);
            } catch (GltfReader.TooManyTrianglesException e) {
                problems.add(field, "draws " + e.triangles() + " triangles; this server's limit is " + left
                        + " more (all meshes together, studio.limits.max-triangles)");
                return null;
            } catch (IllegalArgumentException e) {
                problems.add(field, "is not a glTF 2.0 model that can be drawn: " + e.getMessage());
                return null;
            }
            if (digest != null) {
                cache.keepModel(digest, model);
            }
        }
        if (model.triangleCount() > budget.left()) {
            problems.add(field, "draws " + model.triangleCount() + " triangles; this server's limit is "
                    + Math.max(0, budget.left()) + " more (all meshes together, studio.limits.max-triangles)");
            return null;
        }
        return model;
    }
}

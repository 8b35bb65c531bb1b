package studio.server.scene.compiling;

import static studio.server.scene.compiling.FormatValues.or;
import static studio.server.scene.compiling.FormatValues.vec;

import java.util.ArrayList;
import java.util.List;

import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.material.Material;
import studio.engine.memory.MemoryGate;
import studio.engine.scene.SceneObject;
import studio.engine.texture.Texture;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.SceneDefaults;
import studio.server.scene.format.SceneLimits;

/**
 * The objects of one scene, each a shape and its material, up to the server's limit. Spheres,
 * boxes and planes map here; meshes through {@link MeshMapping}.
 *
 * <p>The memory the objects take is asked of the {@link MemoryGate} first: {@value #BYTES_PER_OBJECT}
 * bytes an object for its engine shape, material and place in the scene (measured over 100,000 of
 * each kind, what the compiled scene keeps: 393 for a rotated box, the largest, 233 for a sphere)
 * and the scene BVH's build (about 150 while it runs); a mesh's arrays are asked for by the OBJ
 * reader and its BVH build as they go.
 */
final class ObjectMapping {

    static final long BYTES_PER_OBJECT = 640;

    private final SceneLimits limits;
    private final MeshMapping meshes;
    private final GltfMapping models;
    private final TextureMapping textures;
    private final MemoryGate memory;
    private final MappingProblems problems;

    ObjectMapping(SceneLimits limits, MeshCache cache, MeshFiles files, MeshAssets assets, TextureCache imageCache,
                  ImageAssets images, MemoryGate memory, MappingProblems problems) {
        this.limits = limits;
        TriangleBudget triangles = new TriangleBudget(limits.maxTriangles());
        this.meshes = new MeshMapping(triangles, cache, files, assets, memory, problems);
        this.models = new GltfMapping(triangles, cache, imageCache, files, assets, memory, problems);
        this.textures = new TextureMapping(imageCache, files, images, memory, problems);
        this.memory = memory;
        this.problems = problems;
    }

    /**
     * The objects that map (a problem for each that does not, and for those beyond the limit). A glTF
     * model is an object for each of its materials, and each counts towards the limit.
     */
    List<SceneObject> of(List<ObjectDto> dtos) {
        problems.atMost("objects", dtos.size(), limits.maxObjects(), "objects");
        memory.reserve(BYTES_PER_OBJECT * Math.min(dtos.size(), limits.maxObjects()));
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < dtos.size() && i < limits.maxObjects(); i++) {
            ObjectDto o = dtos.get(i);
            String path = "objects[" + i + "]";
            if (o instanceof ObjectDto.Gltf gltf) {
                List<SceneObject> parts = models.of(gltf, path);
                memory.reserve(BYTES_PER_OBJECT * Math.max(0, parts.size() - 1));
                objects.addAll(parts);
                if (objects.size() > limits.maxObjects()) {
                    problems.add(path, "brings the scene to " + objects.size() + " objects (one for each of a "
                            + "model's materials); this server's limit is " + limits.maxObjects());
                    break;
                }
                continue;
            }
            Shape shape = o instanceof ObjectDto.Mesh mesh ? meshes.of(mesh, path)
                    : problems.attempt(path, () -> shape(o));
            Material material = problems.attempt(path + ".material", () -> MaterialMapping.of(o.material()));
            if (material != null && o.material() != null && o.material().texture() != null) {
                Texture texture = textures.of(o.material().texture(), path + ".material.texture");
                material = texture != null ? material.withTexture(texture) : null;
            }
            if (shape != null && material != null) {
                objects.add(new SceneObject(shape, material));
            }
        }
        return objects;
    }

    private static Shape shape(ObjectDto o) {
        if (o instanceof ObjectDto.Sphere s) {
            return new Sphere(vec(or(s.center(), SceneDefaults.SPHERE_CENTER)), or(s.radius(), SceneDefaults.SPHERE_RADIUS));
        }
        if (o instanceof ObjectDto.Box b) {
            return new Box(vec(or(b.center(), SceneDefaults.BOX_CENTER)), vec(or(b.size(), SceneDefaults.BOX_SIZE)),
                    vec(or(b.rotation(), SceneDefaults.ORIGIN)));
        }
        ObjectDto.Plane p = (ObjectDto.Plane) o;
        return new Plane(vec(or(p.point(), SceneDefaults.ORIGIN)), vec(or(p.normal(), SceneDefaults.PLANE_NORMAL)));
    }
}

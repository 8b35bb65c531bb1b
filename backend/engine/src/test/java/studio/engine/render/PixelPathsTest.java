package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;

import org.junit.jupiter.api.Test;

import studio.engine.accel.Aabb;
import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Sphere;
import studio.engine.light.Light;
import studio.engine.light.PointLight;
import studio.engine.light.SphereLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneEdit;
import studio.engine.scene.SceneObject;

/**
 * A one-sample film kept with its pixels' paths and rendered again after an edit, only where the
 * edit can reach, comes out as a fresh render of the edited scene, to the bit: the scene is 60
 * small spheres and boxes (chalk, plastic, metal and mirrors) over a floor under three lights,
 * edited as a live view edits it (moving objects, a mirror among them, changing a colour).
 */
class PixelPathsTest {

    private static final int WIDTH = 96, HEIGHT = 72;

    private static RenderSettings oneSample() {
        return new RenderSettings(WIDTH, HEIGHT, Sampler.of("sobol", 1), 4, 2, 42L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, 0);
    }

    private static List<SceneObject> objects(Scene scene) {
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < scene.objectCount(); i++) {
            objects.add(new SceneObject(scene.shape(i), scene.material(i)));
        }
        return objects;
    }

    private static Scene edited(Scene scene, int index, UnaryOperator<SceneObject> edit) {
        List<SceneObject> objects = objects(scene);
        objects.set(index, edit.apply(objects.get(index)));
        return new Scene(scene.camera(), objects, scene.lights(), scene.background(), scene.ambient());
    }

    private static SceneObject moved(SceneObject object, Vec3 by) {
        if (object.shape() instanceof Sphere s) {
            return new SceneObject(new Sphere(s.center().plus(by), s.radius()), object.material());
        }
        Box b = (Box) object.shape();
        return new SceneObject(new Box(b.center().plus(by), b.size(), b.rotationDegrees()), object.material());
    }

    private static RenderResult render(Scene scene, Film film, PixelPaths paths) {
        return Renderer.render(RenderRequest.of(scene, oneSample()).into(film, PixelLattice.ALL, null).recording(paths));
    }

    /** The pixels a render of {@code scene} with {@code paths} renders: those it does not keep. */
    private static long rendered(PixelPaths paths, Scene scene) {
        return render(scene, new Film(WIDTH, HEIGHT), paths).samplesTaken();
    }

    private static int firstOf(Scene scene, MaterialKind kind) {
        for (int i = 0; i < scene.objectCount(); i++) {
            if (scene.material(i).kind() == kind && scene.shape(i) instanceof Sphere) {
                return i;
            }
        }
        throw new AssertionError("no sphere of " + kind);
    }

    /**
     * Renders {@code before} with paths, forgets what the edit to {@code after} reaches, renders
     * {@code after} into the same film, and compares with a fresh render of {@code after}.
     *
     * @return the share of pixels kept
     */
    private static double keptAfterEdit(Scene before, Scene after) {
        return keptAfterEdit(before, after, true);
    }

    /** As {@link #keptAfterEdit(Scene, Scene)}, the edit told by its shapes (a sphere's ball tested) or by their boxes only. */
    private static double keptAfterEdit(Scene before, Scene after, boolean byShapes) {
        Film film = new Film(WIDTH, HEIGHT);
        PixelPaths paths = new PixelPaths(WIDTH, HEIGHT);
        render(before, film, paths);
        if (byShapes) {
            paths.forgetShapes(SceneEdit.changedShapes(before, after, origins(before, after)), after.camera().position(),
                    after.lights());
        } else {
            paths.forget(changedBoxes(before, after), after.camera().position(), after.lights());
        }
        RenderResult again = render(after, film, paths);
        long kept = WIDTH * HEIGHT - again.samplesTaken();

        Film fresh = Renderer.render(RenderRequest.of(after, oneSample())).film();
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(fresh.get(x, y, c), film.get(x, y, c), "pixel " + x + "," + y);
                }
            }
        }
        return (double) kept / (WIDTH * HEIGHT);
    }

    @Test
    void aMovedSphereLeavesTheRestOfTheImage() {
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        int plastic = firstOf(scene, MaterialKind.PLASTIC);
        double kept = keptAfterEdit(scene, edited(scene, plastic, o -> moved(o, new Vec3(0.15, 0.05, 0))));
        assertTrue(kept > 0.5 && kept < 1, "kept " + kept);
    }

    /** Under a sphere light a shadow ray may end anywhere on it: an edit forgets every pixel, and the kept film is still a fresh render. */
    @Test
    void underALightWithASizeAMovedSphereForgetsEveryPixel() {
        Scene points = OpaqueShadowsUnchangedTest.scene();
        List<Light> lights = new ArrayList<>(points.lights());
        lights.add(new SphereLight(new Vec3(-2, 5, 2), 0.6, Rgb.WHITE, 0.5, false));
        Scene scene = new Scene(points.camera(), objects(points), lights, points.background(), points.ambient());
        int plastic = firstOf(scene, MaterialKind.PLASTIC);
        assertEquals(0, keptAfterEdit(scene, edited(scene, plastic, o -> moved(o, new Vec3(0.15, 0.05, 0)))));
    }

    @Test
    void aMovedMirrorChangesWhatItReflectsAndNothingElse() {
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        int mirror = firstOf(scene, MaterialKind.MIRROR);
        double kept = keptAfterEdit(scene, edited(scene, mirror, o -> moved(o, new Vec3(-0.2, 0, 0.1))));
        assertTrue(kept > 0.5 && kept < 1, "kept " + kept);
    }

    /**
     * A moved sphere forgets the pixels whose rays pass near its ball, before and after, not all
     * of those that cross its box (whose corners stand out of the ball): fewer pixels, and the film
     * is still a fresh render of the edited scene.
     */
    @Test
    void aMovedSphereForgetsWhatPassesNearItsBallNotAllOfItsBox() {
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        for (MaterialKind kind : new MaterialKind[] {MaterialKind.PLASTIC, MaterialKind.MIRROR}) {
            int sphere = firstOf(scene, kind);
            Scene after = edited(scene, sphere, o -> moved(o, new Vec3(-0.2, 0, 0.1)));
            double byBalls = keptAfterEdit(scene, after, true), byBoxes = keptAfterEdit(scene, after, false);
            assertTrue(byBalls > byBoxes && byBoxes > 0.5, kind + ": kept " + byBalls + " by the balls, " + byBoxes + " by the boxes");
        }
    }

    @Test
    void aBoxMovedIntoTheLightAndAColourChanged() {
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        Scene movedBox = edited(scene, 1, o -> moved(o, new Vec3(0, 0.4, 0.3)));
        assertTrue(keptAfterEdit(scene, movedBox) < 1);
        int metal = firstOf(scene, MaterialKind.METAL);
        Scene recoloured = edited(scene, metal, o -> new SceneObject(o.shape(),
                MaterialDefaults.of(MaterialKind.METAL, new Rgb(0.9, 0.1, 0.1))));
        assertTrue(keptAfterEdit(scene, recoloured) < 1);
    }

    @Test
    void keptPixelsWouldBeWrongWithoutForgetting() {
        // the check above can fail: keeping every pixel through the same edit gives another image
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        Scene after = edited(scene, firstOf(scene, MaterialKind.MIRROR), o -> moved(o, new Vec3(-0.2, 0, 0.1)));
        Film film = new Film(WIDTH, HEIGHT);
        PixelPaths paths = new PixelPaths(WIDTH, HEIGHT);
        render(scene, film, paths);
        RenderResult again = render(after, film, paths);
        assertTrue(again.samplesTaken() < WIDTH * HEIGHT / 10, "nearly every pixel kept: " + again.samplesTaken());
        assertNotEquals(SampledImagesUnchangedTest.fingerprint(Renderer.render(RenderRequest.of(after, oneSample())).film()),
                SampledImagesUnchangedTest.fingerprint(film));
    }

    @Test
    void theMosaicsLatticesRenderIntoKeptPathsAsAWholeRender() {
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        Film film = new Film(WIDTH, HEIGHT);
        PixelPaths paths = new PixelPaths(WIDTH, HEIGHT);
        PixelLattice before = null;
        for (PixelLattice lattice : List.of(new PixelLattice(8, 4), new PixelLattice(4, 0), new PixelLattice(2, 0),
                PixelLattice.ALL)) {
            Renderer.render(RenderRequest.of(scene, oneSample()).into(film, lattice, before).recording(paths));
            before = lattice;
        }
        assertEquals(SampledImagesUnchangedTest.fingerprint(Renderer.render(RenderRequest.of(scene, oneSample())).film()),
                SampledImagesUnchangedTest.fingerprint(film));
        long again = rendered(paths, scene);
        assertTrue(again < WIDTH * HEIGHT / 10, "rendered again " + again);
    }

    @Test
    void glassAndSeveralSamplesAreNotKept() {
        Scene opaque = OpaqueShadowsUnchangedTest.scene();
        List<SceneObject> objects = objects(opaque);
        objects.add(new SceneObject(new Sphere(new Vec3(0, 1, 0), 1.2),
                MaterialDefaults.of(MaterialKind.GLASS, Rgb.WHITE)));
        Scene glass = new Scene(opaque.camera(), objects, opaque.lights(), opaque.background(), opaque.ambient());
        PixelPaths paths = new PixelPaths(WIDTH, HEIGHT);
        render(glass, new Film(WIDTH, HEIGHT), paths);
        int centre = 0;
        for (int y = HEIGHT / 2 - 2; y <= HEIGHT / 2 + 2; y++) {
            for (int x = WIDTH / 2 - 2; x <= WIDTH / 2 + 2; x++) {
                centre += paths.known(x, y) ? 1 : 0;
            }
        }
        assertEquals(0, centre, "a pixel seeing the glass ball branches and is not kept");
        assertTrue(rendered(paths, glass) < WIDTH * HEIGHT, "the pixels seeing no glass are kept");

        RenderSettings four = new RenderSettings(WIDTH, HEIGHT, Sampler.of("sobol", 4), 4, 2, 42L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, 0);
        PixelPaths fourSamples = new PixelPaths(WIDTH, HEIGHT);
        Renderer.render(RenderRequest.of(opaque, four).into(new Film(WIDTH, HEIGHT), PixelLattice.ALL, null).recording(fourSamples));
        assertEquals(WIDTH * HEIGHT * 4, Renderer.render(RenderRequest.of(opaque, four)
                .into(new Film(WIDTH, HEIGHT), PixelLattice.ALL, null).recording(fourSamples)).samplesTaken(),
                "every pixel rendered again");
    }

    @Test
    void editsThatReachEveryPixel() {
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        Camera turned = new Camera(new Vec3(0.1, 2.5, 5), new Vec3(0, 0.8, -0.5), new Vec3(0, 1, 0), 50);
        assertNull(changedBoxes(scene,
                new Scene(turned, objects(scene), scene.lights(), scene.background(), scene.ambient())));
        List<Light> lights = new ArrayList<>(scene.lights());
        lights.set(0, new PointLight(new Vec3(3, 6, 2.5), Rgb.WHITE, 1, false));
        assertNull(changedBoxes(scene,
                new Scene(scene.camera(), objects(scene), lights, scene.background(), scene.ambient())));
        assertNull(changedBoxes(scene,
                new Scene(scene.camera(), objects(scene), scene.lights(), Rgb.WHITE, scene.ambient())));
        assertNull(changedBoxes(scene,
                new Scene(scene.camera(), objects(scene), scene.lights(), scene.background(), 0.2)));
        assertNull(changedBoxes(scene, new Scene(scene.camera(), objects(scene).subList(0, 30),
                scene.lights(), scene.background(), scene.ambient())), "an object fewer");
        assertNull(changedBoxes(scene, edited(scene, 0, o -> new SceneObject(o.shape(),
                MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE)))), "the floor plane changed");

        PixelPaths paths = new PixelPaths(WIDTH, HEIGHT);
        assertThrows(IllegalArgumentException.class, () -> paths.forget(List.of(Aabb.UNBOUNDED),
                scene.camera().position(), scene.lights()));
    }

    @Test
    void theSameSceneReadAgainIsNoEdit() {
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        Scene again = OpaqueShadowsUnchangedTest.scene(); // new instances of equal values
        assertEquals(List.of(), changedBoxes(scene, again));
        assertTrue(keptAfterEdit(scene, again) > 0.95);
        Scene moved = edited(scene, 5, o -> moved(o, new Vec3(0, 0, 0.01)));
        assertEquals(2, changedBoxes(scene, moved).size(), "the object's box before and after");
        assertFalse(changedBoxes(scene, moved).get(0).equals(changedBoxes(scene, moved).get(1)));
    }

    /** The edit's boxes, its changed objects told as an editor that compares values would tell them. */
    private static List<Aabb> changedBoxes(Scene before, Scene after) {
        return SceneEdit.changedBoxes(before, after, origins(before, after));
    }

    /** The edit's changed objects as an editor that compares values would tell them. */
    private static int[] origins(Scene before, Scene after) {
        int[] origins = new int[after.objectCount()];
        for (int i = 0; i < origins.length; i++) {
            boolean same = i < before.objectCount() && before.shape(i).equals(after.shape(i))
                    && before.material(i).equals(after.material(i));
            origins[i] = same ? i : -1;
        }
        return origins;
    }

    @Test
    void anEditIsWhatItsMakerTellsNotWorkedOutAgain() {
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        int[] unchanged = new int[scene.objectCount()];
        for (int i = 0; i < unchanged.length; i++) {
            unchanged[i] = i;
        }
        assertNull(SceneEdit.changedBoxes(scene, scene, null), "not told: anything may have changed");
        assertEquals(List.of(), SceneEdit.changedBoxes(scene, scene, unchanged));
        int[] toldChanged = unchanged.clone();
        toldChanged[5] = -1;
        assertEquals(2, SceneEdit.changedBoxes(scene, scene, toldChanged).size(), "told changed, though equal");
        List<SceneObject> doubled = new ArrayList<>(objects(scene));
        doubled.addAll(objects(scene).subList(1, scene.objectCount()));
        Scene large = new Scene(scene.camera(), doubled, scene.lights(), scene.background(), scene.ambient());
        int[] many = new int[large.objectCount()];
        for (int i = 0; i < many.length; i++) {
            many[i] = i > SceneEdit.MAX_CHANGED + 1 ? i : -1;
        }
        many[0] = 0; // the plane unchanged
        assertNull(SceneEdit.changedBoxes(large, large, many), "too many to forget pixel by pixel");
        many[SceneEdit.MAX_CHANGED + 1] = SceneEdit.MAX_CHANGED + 1;
        assertEquals(2 * SceneEdit.MAX_CHANGED, SceneEdit.changedBoxes(large, large, many).size());
    }

    private static void forget(PixelPaths paths, Scene before, Scene after) {
        paths.forget(changedBoxes(before, after), after.camera().position(), after.lights());
    }

    private static void assertSameFilm(Film expected, Film actual) {
        assertEquals(SampledImagesUnchangedTest.fingerprint(expected), SampledImagesUnchangedTest.fingerprint(actual));
    }

    @Test
    void editsNotedBeforeAndDuringARenderAllCount() {
        // as in a drag: an edit, a coarse pass cut short by the next edit, then the whole film
        Scene a = OpaqueShadowsUnchangedTest.scene();
        int mirror = firstOf(a, MaterialKind.MIRROR), plastic = firstOf(a, MaterialKind.PLASTIC);
        Scene b = edited(a, mirror, o -> moved(o, new Vec3(-0.2, 0, 0.1)));
        Scene c = edited(b, plastic, o -> moved(o, new Vec3(0.1, 0.1, 0)));
        Scene d = edited(c, mirror, o -> moved(o, new Vec3(0.1, 0.05, 0)));
        Film film = new Film(WIDTH, HEIGHT);
        PixelPaths paths = new PixelPaths(WIDTH, HEIGHT);
        render(a, film, paths);
        forget(paths, a, b);
        Renderer.render(RenderRequest.of(b, oneSample()).into(film, new PixelLattice(8, 4), null).recording(paths));
        forget(paths, b, c);
        forget(paths, c, d);
        RenderResult last = render(d, film, paths);
        assertSameFilm(Renderer.render(RenderRequest.of(d, oneSample())).film(), film);
        assertTrue(last.samplesTaken() < WIDTH * HEIGHT / 4, "rendered " + last.samplesTaken());
    }

    @Test
    void pixelsOlderThanTheEditsNotedAreRenderedAgain() {
        Scene a = OpaqueShadowsUnchangedTest.scene();
        Scene far = edited(a, 1, o -> new SceneObject(new Sphere(new Vec3(0, 2.5, 9), 0.1), o.material()));
        Scene farther = edited(far, 1, o -> new SceneObject(new Sphere(new Vec3(0, 2.5, 9.5), 0.1), o.material()));
        PixelPaths once = new PixelPaths(WIDTH, HEIGHT), untouched = new PixelPaths(WIDTH, HEIGHT);
        render(a, new Film(WIDTH, HEIGHT), once);
        render(a, new Film(WIDTH, HEIGHT), untouched);
        forget(once, a, far); // the first edit reaches some pixels (the object's old place)
        forget(untouched, a, far);
        for (int i = 0; i < PixelPaths.MAX_EDITS - 1; i++) {
            forget(untouched, i % 2 == 0 ? far : farther, i % 2 == 0 ? farther : far);
        }
        long afterFirst = rendered(once, far);
        assertTrue(afterFirst < WIDTH * HEIGHT, "rendered after the first edit " + afterFirst);
        assertEquals(afterFirst, rendered(untouched, far), "edits behind the camera reach nothing");
        PixelPaths stale = new PixelPaths(WIDTH, HEIGHT);
        render(a, new Film(WIDTH, HEIGHT), stale);
        for (int i = 0; i <= PixelPaths.MAX_EDITS; i++) {
            stale.forget(List.of(new Aabb(0, 2.5, 9, 0.1, 2.6, 9.1)), a.camera().position(), a.lights());
        }
        assertEquals(WIDTH * HEIGHT, rendered(stale, a), "tested against none of more edits than are noted");

        PixelPaths unedited = new PixelPaths(WIDTH, HEIGHT), many = new PixelPaths(WIDTH, HEIGHT);
        PixelPaths tooMany = new PixelPaths(WIDTH, HEIGHT);
        render(a, new Film(WIDTH, HEIGHT), unedited);
        render(a, new Film(WIDTH, HEIGHT), many);
        render(a, new Film(WIDTH, HEIGHT), tooMany);
        List<Aabb> behind = new ArrayList<>();
        for (int i = 0; i < PixelPaths.MAX_BOXES; i++) {
            behind.add(new Aabb(0, 2.5, 9 + i, 0.1, 2.6, 9.1 + i)); // behind the camera: they reach nothing
        }
        many.forget(behind, a.camera().position(), a.lights());
        long notKept = rendered(unedited, a);
        assertTrue(notKept < WIDTH * HEIGHT / 10, "rendered with no edit " + notKept);
        assertEquals(notKept, rendered(many, a), "as many boxes as are tested one by one");
        behind.add(new Aabb(0, 2.5, 50, 0.1, 2.6, 50.1));
        tooMany.forget(behind, a.camera().position(), a.lights());
        assertEquals(WIDTH * HEIGHT, rendered(tooMany, a), "one box more: every pixel rendered again, not tested against each");
    }

    @Test
    void randomEditSequencesWithPassesCutShortEndAsFreshRenders() {
        // what a drag and an editor do, at random: move, resize, recolour, turn a sphere to glass and
        // back, add nothing, move the camera or a light; between edits a pass over a random lattice,
        // sometimes cut short after a random number of tiles; after each sequence the whole film
        java.util.Random random = new java.util.Random(2026);
        Scene scene = OpaqueShadowsUnchangedTest.scene();
        Film film = new Film(WIDTH, HEIGHT);
        PixelPaths paths = new PixelPaths(WIDTH, HEIGHT);
        render(scene, film, paths);
        MaterialKind[] kinds = MaterialKind.values();
        int rendered = 0;
        for (int step = 0; step < 40; step++) {
            int index = 1 + random.nextInt(scene.objectCount() - 1);
            int what = random.nextInt(10);
            Scene next;
            if (what < 5) {
                Vec3 by = new Vec3(random.nextGaussian() * 0.2, random.nextGaussian() * 0.1, random.nextGaussian() * 0.2);
                next = edited(scene, index, o -> moved(o, by));
            } else if (what < 7) {
                MaterialKind kind = kinds[random.nextInt(kinds.length)];
                Rgb colour = new Rgb(random.nextDouble(), random.nextDouble(), random.nextDouble());
                next = edited(scene, index, o -> new SceneObject(o.shape(), MaterialDefaults.of(kind, colour)));
            } else if (what < 8) {
                next = edited(scene, index, o -> o.shape() instanceof Sphere s
                        ? new SceneObject(new Sphere(s.center(), s.radius() * (0.5 + random.nextDouble())), o.material())
                        : o);
            } else if (what < 9) {
                List<Light> lights = new ArrayList<>(scene.lights());
                PointLight l = (PointLight) lights.get(0);
                lights.set(0, new PointLight(l.position().plus(new Vec3(0.1, 0, 0)), l.color(), l.intensity(),
                        l.falloff()));
                next = new Scene(scene.camera(), objects(scene), lights, scene.background(), scene.ambient());
            } else {
                next = scene; // the same scene again
            }
            List<Aabb> boxes = changedBoxes(scene, next);
            if (boxes == null) {
                paths.forgetAll();
            } else {
                paths.forget(boxes, next.camera().position(), next.lights());
            }
            scene = next;
            int tiles = random.nextInt(30);
            PixelLattice lattice = List.of(new PixelLattice(8, 4), new PixelLattice(4, 0), PixelLattice.ALL)
                    .get(random.nextInt(3));
            java.util.concurrent.atomic.AtomicInteger asked = new java.util.concurrent.atomic.AtomicInteger();
            try {
                rendered += (int) Renderer.render(RenderRequest.of(scene, oneSample()).into(film, lattice, null).recording(paths).cancelledWhen(() -> asked.incrementAndGet() > tiles)).samplesTaken();
            } catch (RenderCancelledException e) {
                // cut short: the pixels it finished are known, the others not
            }
            if (step % 8 == 7) {
                rendered += (int) render(scene, film, paths).samplesTaken();
                assertSameFilm(Renderer.render(RenderRequest.of(scene, oneSample())).film(), film);
            }
        }
        assertTrue(rendered < 40 * WIDTH * HEIGHT / 2, "most pixels kept over the edits: rendered " + rendered);
    }
}

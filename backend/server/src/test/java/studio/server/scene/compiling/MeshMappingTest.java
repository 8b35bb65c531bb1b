package studio.server.scene.compiling;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.engine.accel.Aabb;
import studio.engine.geometry.TriangleMesh;
import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.MeshFileNames;
import studio.server.scene.format.SceneDto;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;
import studio.server.scene.reading.SceneValidationTest;

/** The {@code mesh} object: inline OBJ text or a file, placed by scale, rotation and position; every bad form named. */
class MeshMappingTest {

    /** A unit tetrahedron: 4 vertices, 4 triangles. */
    private static final String TETRAHEDRON = "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nv 0 0 1\\n"
            + "f 1 3 2\\nf 1 2 4\\nf 1 4 3\\nf 2 3 4\\n";
    private static final String TETRAHEDRON_FILE_TEXT = TETRAHEDRON.replace("\\n", "\n");

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader READER = new SceneReader(VALIDATION.getValidator());

    @TempDir
    Path dir;

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    private static CompiledScene map(String objects, SceneLimits limits, MeshFiles files) {
        String json = "{'image':{'width':8,'height':6},'render':{'samples':1,'maxDepth':1},'objects':[" + objects + "]}";
        return new SceneMapper(limits).map(READER.read(SceneValidationTest.json(json)), 0,
                files);
    }

    private static List<FieldProblem> problems(String objects, SceneLimits limits, MeshFiles files) {
        InvalidSceneException e = catchThrowableOfType(InvalidSceneException.class, () -> map(objects, limits, files));
        assertThat(e).as("expected the scene to be refused").isNotNull();
        return e.problems();
    }

    private static FieldProblem onlyProblem(String objects, MeshFiles files) {
        List<FieldProblem> problems = problems(objects, SceneLimits.DEFAULTS, files);
        assertThat(problems).hasSize(1);
        return problems.get(0);
    }

    @Test
    void mapsAnInlineObjToATriangleMeshPlacedByScaleRotationAndPosition() {
        CompiledScene compiled = map("{'type':'mesh','obj':'" + TETRAHEDRON + "','position':[10,0,0],'scale':2,"
                + "'rotation':[0,0,90],'material':{'type':'plastic','color':'#ff0000'}}", SceneLimits.DEFAULTS,
                MeshFiles.none());

        TriangleMesh mesh = (TriangleMesh) compiled.scene().shape(0);
        assertThat(mesh.triangleCount()).isEqualTo(4);
        // scaled by 2, turned 90 degrees about z (x -> y, y -> -x), moved by 10 along x
        Aabb b = mesh.bounds();
        assertThat(b.minX()).isCloseTo(8, org.assertj.core.data.Offset.offset(1e-6));
        assertThat(b.maxX()).isCloseTo(10, org.assertj.core.data.Offset.offset(1e-6));
        assertThat(b.maxY()).isCloseTo(2, org.assertj.core.data.Offset.offset(1e-6));
        assertThat(b.maxZ()).isCloseTo(2, org.assertj.core.data.Offset.offset(1e-6));
    }

    @Test
    void readsAMeshFileBesideTheScene() throws IOException {
        Files.createDirectories(dir.resolve("meshes"));
        Files.writeString(dir.resolve("meshes/tetra.obj"), TETRAHEDRON_FILE_TEXT);

        CompiledScene compiled = map("{'type':'mesh','file':'meshes/tetra.obj'}", SceneLimits.DEFAULTS,
                MeshFiles.in(dir));

        assertThat(((TriangleMesh) compiled.scene().shape(0)).triangleCount()).isEqualTo(4);
    }

    @Test
    void needsExactlyOneOfObjFileAndAsset() {
        assertThat(onlyProblem("{'type':'mesh'}", MeshFiles.none()).field()).isEqualTo("objects[0]");
        FieldProblem both = onlyProblem("{'type':'mesh','obj':'" + TETRAHEDRON + "','file':'a.obj'}", MeshFiles.none());
        assertThat(both.field()).isEqualTo("objects[0]");
        assertThat(both.message()).contains("not more");
    }

    @Test
    void namesTheObjLineThatIsWrong() {
        FieldProblem p = onlyProblem("{'type':'mesh','obj':'v 0 0 0\\nv 1 0 0\\nf 1 2 7\\n'}", MeshFiles.none());
        assertThat(p.field()).isEqualTo("objects[0].obj");
        assertThat(p.message()).contains("line 3");
    }

    @Test
    void refusesAMeshWithNoTriangles() {
        FieldProblem p = onlyProblem("{'type':'mesh','obj':'v 0 0 0\\nv 1 0 0\\n'}", MeshFiles.none());
        assertThat(p.field()).startsWith("objects[0]");
    }

    @Test
    void refusesFileNamesThatLeaveTheFolderOrAreNotObj() {
        for (String bad : List.of("../secret.obj", "/etc/passwd.obj", "meshes/../../x.obj", "a\\\\b.obj", "mesh.txt",
                "")) {
            FieldProblem p = onlyProblem("{'type':'mesh','file':'" + bad + "'}", MeshFiles.in(dir));
            assertThat(p.field()).as(bad).isEqualTo("objects[0].file");
            assertThat(p.message()).as(bad).contains("relative path");
        }
    }

    @Test
    void refusesFolderOrFileNamesThatStartWithADotOrAreEmpty() {
        for (String bad : List.of(".hidden.obj", "meshes/.x.obj", "meshes//x.obj", "meshes/.obj", "a/.b/c.obj", ".obj")) {
            FieldProblem p = onlyProblem("{'type':'mesh','file':'" + bad + "'}", MeshFiles.in(dir));
            assertThat(p.message()).as(bad).contains("relative path");
        }
    }

    @Test
    void checksAFileNameOfTenThousandFoldersWithoutOverflowingTheStack() {
        String deep = "a/".repeat(10_000) + "x.obj";
        assertThat(MeshFileNames.PATTERN.matcher(deep).matches()).isTrue();
        assertThat(onlyProblem("{'type':'mesh','file':'" + deep + "'}", MeshFiles.bundled()).message())
                .contains("ships with this server");
    }

    @Test
    void saysWhenTheFileIsMissingOrCannotBeReadHere() {
        assertThat(onlyProblem("{'type':'mesh','file':'missing.obj'}", MeshFiles.in(dir)).message())
                .contains("no such file");
        FieldProblem notBundled = onlyProblem("{'type':'mesh','file':'meshes/missing.obj'}", MeshFiles.bundled());
        assertThat(notBundled.field()).isEqualTo("objects[0].file");
        assertThat(notBundled.message()).contains("inline");
        assertThat(onlyProblem("{'type':'mesh','file':'a.obj'}", MeshFiles.none()).message()).contains("inline");
    }

    @Test
    void countsEveryMeshsTrianglesAgainstTheLimit() {
        SceneLimits sixTriangles = new SceneLimits(64, 48, 9, 3, 10, 1, 6, 10_000);
        String tetra = "{'type':'mesh','obj':'" + TETRAHEDRON + "'}";

        assertThat(map(tetra, sixTriangles, MeshFiles.none()).scene().objectCount()).isEqualTo(1);
        List<FieldProblem> problems = problems(tetra + "," + tetra, sixTriangles, MeshFiles.none());
        assertThat(problems).extracting(FieldProblem::field).containsExactly("objects[1].obj");
        assertThat(problems.get(0).message()).contains("more than 2 triangles").contains("limit is 2 more");
    }

    @Test
    void stopsReadingAMeshAtTheTriangleLimit() {
        // one polygon of a million corners: 999,998 triangles in its fan, the limit 1,000
        SceneLimits thousand = new SceneLimits(64, 48, 9, 3, 10, 1, 1000, 10_000_000);
        SceneDto scene = READER.read(SceneValidationTest.json("{'image':{'width':8,'height':6},"
                + "'render':{'samples':1,'maxDepth':1},'objects':[{'type':'mesh','obj':'"
                + "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf" + " 1".repeat(1_000_000) + "'}]}"));
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long before = threads.getThreadAllocatedBytes(Thread.currentThread().getId());

        InvalidSceneException e = catchThrowableOfType(InvalidSceneException.class,
                () -> new SceneMapper(thousand).map(scene, 0));

        long allocated = threads.getThreadAllocatedBytes(Thread.currentThread().getId()) - before;
        // the line is buffered (2 M chars, 8 MiB with its growth); reading all its corners took 70 MiB more
        assertThat(allocated).isLessThan(12L << 20);
        assertThat(e.problems()).extracting(FieldProblem::field).containsExactly("objects[0].obj");
        assertThat(e.problems().get(0).message()).contains("more than 1000 triangles").contains("OBJ line 4");
    }

    @Test
    void rejectsANonPositiveScaleAndBadVectorsByPath() {
        assertThat(SceneValidationTest.problems("{'objects':[{'type':'mesh','obj':'x','scale':0}]}"))
                .extracting(FieldProblem::field).containsExactly("objects[0].scale");
        assertThat(SceneValidationTest.problems("{'objects':[{'type':'mesh','obj':'x','position':[1,2]}]}"))
                .extracting(FieldProblem::field).containsExactly("objects[0].position");
        assertThat(SceneValidationTest.problems("{'objects':[{'type':'mesh','obj':5}]}"))
                .extracting(FieldProblem::field).containsExactly("objects[0].obj");
    }
}

package studio.server.scene.compiling;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;

import javax.imageio.ImageIO;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.engine.material.Material;
import studio.engine.material.MaterialKind;
import studio.engine.texture.CheckerTexture;
import studio.engine.texture.ImageTexture;
import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;
import studio.server.scene.reading.SceneValidationTest;
import studio.server.system.MemoryBudget;

/** A material's {@code texture}: checker and image (asset or file), and every bad form named by its field. */
class TextureMappingTest {

    private static final String ID = "sha256-" + "ab".repeat(32);
    private static final String FIELD = "objects[0].material.texture";

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader READER = new SceneReader(VALIDATION.getValidator());

    @TempDir
    Path dir;

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    private static Material map(String material, SceneMapper mapper, MeshFiles files) {
        String json = "{'image':{'width':8,'height':6},'render':{'samples':1,'maxDepth':1},'objects':["
                + "{'type':'plane','material':" + material + "}]}";
        return mapper.map(READER.read(SceneValidationTest.json(json)), 0, files).scene().material(0);
    }

    private static Material map(String material) {
        return map(material, new SceneMapper(SceneLimits.DEFAULTS), MeshFiles.none());
    }

    private static List<FieldProblem> problems(String material, ImageAssets assets) {
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, MeshCache.none(), MeshAssets.none(),
                TextureCache.none(), assets);
        InvalidSceneException e = catchThrowableOfType(InvalidSceneException.class,
                () -> map(material, mapper, MeshFiles.none()));
        assertThat(e).as("expected the scene to be refused").isNotNull();
        return e.problems();
    }

    private static List<FieldProblem> problems(String material) {
        return problems(material, ImageAssets.none());
    }

    static byte[] png(int width, int height) throws IOException {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, (x + y) % 2 == 0 ? 0xff0000 : 0x0000ff);
            }
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(image, "png", out);
        return out.toByteArray();
    }

    @Test
    void mapsACheckerOntoAnyMaterialItsColourMultiplies() {
        Material m = map("{'type':'chalk','color':'#ffffff','texture':{'type':'checker','colors':['#000000','#ffffff'],"
                + "'size':0.5}}");
        assertThat(m.texture()).isEqualTo(new CheckerTexture(studio.engine.math.Rgb.BLACK, studio.engine.math.Rgb.WHITE,
                0.5));
    }

    @Test
    void aTextureOnAFlatMaterialIsFine() {
        Material m = map("{'type':'flat','color':'#808080','texture':{'type':'checker','colors':['#000000','#ffffff']}}");
        assertThat(m.kind()).isEqualTo(MaterialKind.FLAT);
        assertThat(((CheckerTexture) m.texture()).size()).isEqualTo(1);
    }

    @Test
    void aMaterialWithoutTextureHasNone() {
        assertThat(map("{'type':'plastic','color':'#808080'}").texture()).isNull();
    }

    @Test
    void rejectsAnUnknownTextureType() {
        assertThat(problems("{'type':'chalk','texture':{'type':'marble'}}"))
                .anySatisfy(p -> assertThat(p.field()).startsWith(FIELD));
    }

    @Test
    void rejectsColorsThatAreNotExactlyTwo() {
        for (String colors : List.of("['#000000']", "['#000000','#ffffff','#ff0000']", "[]")) {
            assertThat(problems("{'type':'chalk','texture':{'type':'checker','colors':" + colors + "}}"))
                    .singleElement().satisfies(p -> {
                        assertThat(p.field()).isEqualTo(FIELD + ".colors");
                        assertThat(p.message()).contains("exactly two colours");
                    });
        }
        assertThat(problems("{'type':'chalk','texture':{'type':'checker'}}"))
                .singleElement().satisfies(p -> assertThat(p.field()).isEqualTo(FIELD + ".colors"));
    }

    @Test
    void rejectsAColourThatIsNotOne() {
        assertThat(problems("{'type':'chalk','texture':{'type':'checker','colors':['#000000','red']}}"))
                .singleElement().satisfies(p -> {
                    assertThat(p.field()).startsWith(FIELD + ".colors");
                    assertThat(p.message()).contains("#rrggbb");
                });
    }

    @Test
    void rejectsASizeThatIsNotFiniteAndPositive() {
        for (String size : List.of("0", "-1", "1e999")) {
            assertThat(problems("{'type':'chalk','texture':{'type':'checker','colors':['#000000','#ffffff'],'size':"
                    + size + "}}")).singleElement().satisfies(p -> assertThat(p.field()).isEqualTo(FIELD + ".size"));
        }
    }

    @Test
    void rejectsAScaleThatIsNotTwoFinitePositiveNumbers() {
        assertThat(problems("{'type':'chalk','texture':{'type':'image','asset':'" + ID + "','scale':[1]}}",
                id -> new byte[0]))
                .singleElement().satisfies(p -> assertThat(p.field()).isEqualTo(FIELD + ".scale"));
        for (String scale : List.of("[1,0]", "[1,-2]", "[1,1e999]")) {
            assertThat(problems("{'type':'chalk','texture':{'type':'image','asset':'" + ID + "','scale':" + scale + "}}"))
                    .singleElement().satisfies(p -> assertThat(p.field()).startsWith(FIELD + ".scale"));
        }
    }

    @Test
    void namesTheFieldAndTheIdOfAMissingAsset() {
        assertThat(problems("{'type':'chalk','texture':{'type':'image','asset':'" + ID + "'}}", id -> null))
                .singleElement().satisfies(p -> {
                    assertThat(p.field()).isEqualTo(FIELD + ".asset");
                    assertThat(p.message()).contains(ID).contains("POST /api/assets");
                });
    }

    @Test
    void rejectsAnAssetThatIsNotAnImage() {
        ImageAssets meshOnly = id -> {
            throw new IllegalArgumentException("the asset " + id + " is model/obj, not a PNG or JPEG image");
        };
        assertThat(problems("{'type':'chalk','texture':{'type':'image','asset':'" + ID + "'}}", meshOnly))
                .singleElement().satisfies(p -> {
                    assertThat(p.field()).isEqualTo(FIELD + ".asset");
                    assertThat(p.message()).contains("not a PNG or JPEG image");
                });
        assertThat(problems("{'type':'chalk','texture':{'type':'image','asset':'" + ID + "'}}",
                id -> "v 0 0 0\n".getBytes()))
                .singleElement().satisfies(p -> assertThat(p.message()).contains("not a PNG or JPEG image"));
    }

    @Test
    void needsExactlyOneOfAssetAndFile() {
        assertThat(problems("{'type':'chalk','texture':{'type':'image'}}"))
                .singleElement().satisfies(p -> assertThat(p.field()).isEqualTo(FIELD));
        assertThat(problems("{'type':'chalk','texture':{'type':'image','asset':'" + ID + "','file':'a.png'}}"))
                .singleElement().satisfies(p -> assertThat(p.field()).isEqualTo(FIELD));
    }

    @Test
    void decodesAnImageAssetOnceAndKeepsIt() throws IOException {
        byte[] png = png(4, 2);
        AtomicInteger reads = new AtomicInteger();
        TextureCache cache = new TextureCache(1 << 20, MemoryBudget.unlimited());
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, MeshCache.none(), MeshAssets.none(), cache, id -> {
            reads.incrementAndGet();
            return png;
        });
        String material = "{'type':'chalk','texture':{'type':'image','asset':'" + ID + "','scale':[2,3]}}";
        ImageTexture first = (ImageTexture) map(material, mapper, MeshFiles.none()).texture();
        ImageTexture second = (ImageTexture) map(material, mapper, MeshFiles.none()).texture();

        assertThat(first.image().width()).isEqualTo(4);
        assertThat(first.image().height()).isEqualTo(2);
        assertThat(first.scaleU()).isEqualTo(2);
        assertThat(first.scaleV()).isEqualTo(3);
        assertThat(second.image()).isSameAs(first.image());
        assertThat(reads).hasValue(1);
        assertThat(cache.bytes()).isEqualTo(first.image().bytes());
    }

    @Test
    void readsAnImageFileBesideTheScene() throws IOException {
        Files.write(dir.resolve("bricks.png"), png(8, 8));
        ImageTexture t = (ImageTexture) map("{'type':'chalk','texture':{'type':'image','file':'bricks.png'}}",
                new SceneMapper(SceneLimits.DEFAULTS), MeshFiles.in(dir)).texture();
        assertThat(t.image().width()).isEqualTo(8);
        assertThat(t.image().height()).isEqualTo(8);
    }

    @Test
    void theServiceReadsNoImageFiles() {
        InvalidSceneException e = catchThrowableOfType(InvalidSceneException.class,
                () -> map("{'type':'chalk','texture':{'type':'image','file':'bricks.png'}}",
                        new SceneMapper(SceneLimits.DEFAULTS), MeshFiles.bundled()));
        assertThat(e.problems()).singleElement().satisfies(p -> {
            assertThat(p.field()).isEqualTo(FIELD + ".file");
            assertThat(p.message()).contains("\"asset\"");
        });
    }
}

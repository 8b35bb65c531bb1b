package studio.server.scene.reading;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.SceneDto;

/**
 * The scene format's rules, checked by {@link SceneReader} (strict JSON, then Bean Validation)
 * without Spring. Every problem must name its field by JSON path and say what is wrong.
 * Scenes are written with single quotes for readability; {@link #json} turns them into JSON (the
 * compiler's tests use it too).
 */
public class SceneValidationTest {

    /** English messages whatever the machine's locale, so the assertions below hold everywhere. */
    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader READER = new SceneReader(VALIDATION.getValidator());

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    // --- helpers -------------------------------------------------------------------------------

    public static byte[] json(String singleQuoted) {
        return singleQuoted.replace('\'', '"').getBytes(StandardCharsets.UTF_8);
    }

    /** The problems reading {@code body} reports; fails if it is accepted. */
    static List<FieldProblem> problems(byte[] body) {
        InvalidSceneException e = catchThrowableOfType(InvalidSceneException.class, () -> READER.read(body));
        assertThat(e).as("expected the scene to be refused: %s", new String(body, StandardCharsets.UTF_8)).isNotNull();
        assertThat(e.problems()).isNotEmpty();
        return e.problems();
    }

    public static List<FieldProblem> problems(String singleQuoted) {
        return problems(json(singleQuoted));
    }

    /** The single problem of a scene, which must be at {@code field}. */
    static FieldProblem onlyProblem(String singleQuoted, String field) {
        List<FieldProblem> problems = problems(singleQuoted);
        assertThat(problems).as("problems").hasSize(1);
        assertThat(problems.get(0).field()).isEqualTo(field);
        return problems.get(0);
    }

    static void assertOnlyProblem(String singleQuoted, String field, String message) {
        assertThat(onlyProblem(singleQuoted, field).message()).isEqualTo(message);
    }

    /** A one-object scene around the given object JSON. */
    static String withObject(String object) {
        return "{'objects':[" + object + "]}";
    }

    // --- baseline --------------------------------------------------------------------------------

    @Test
    void acceptsMinimalScene() {
        SceneDto scene = READER.read(json("{'objects':[]}"));
        assertThat(scene.objects()).isEmpty();
        assertThat(scene.lights()).isNull();
    }

    @Test
    void acceptsEveryKindOfObjectMaterialAndLight() {
        String scene = """
                {'version':1,'name':'all','background':'#A0b1C2','ambient':0.1,
                 'image':{'width':2,'height':3,'format':'jpg','quality':0.5},
                 'camera':{'position':[0,1,5],'lookAt':[0,0,0],'up':[0,1,0],'fov':60},
                 'render':{'sampler':'regular','samples':4,'maxDepth':0,'seed':7},
                 'lights':[{'type':'point','position':[1,2,3],'color':'#ffffff','intensity':0,'falloff':true}],
                 'objects':[
                   {'type':'sphere','center':[0,0,0],'radius':0.5,'material':{'type':'flat','color':'#000000'}},
                   {'type':'box','center':[0,0,0],'size':[1,2,3],'rotation':[0,45,0],
                    'material':{'type':'metal','color':'#ffffff','diffuse':0,'specular':1,'shininess':1,'reflectivity':1}},
                   {'type':'plane','point':[0,0,0],'normal':[0,0,2],'material':{'type':'glass','ior':4}},
                   {'type':'sphere','material':{'type':'mirror','reflectivity':0}},
                   {'type':'sphere','material':{'type':'plastic','shininess':10000}},
                   {'type':'sphere','material':{'type':'chalk','diffuse':1}}]}
                """;
        assertThatCode(() -> READER.read(json(scene))).doesNotThrowAnyException();
    }

    // --- required fields -------------------------------------------------------------------------

    @Test
    void rejectsMissingObjects() {
        assertOnlyProblem("{'name':'empty'}", "objects", "is required (a list of objects, possibly empty)");
    }

    @Test
    void rejectsNullObjects() {
        assertOnlyProblem("{'objects':null}", "objects", "is required (a list of objects, possibly empty)");
    }

    @Test
    void rejectsNullForAFieldThatHasADefault() {
        assertOnlyProblem("{'image':null,'objects':[]}", "image", "must not be null; leave the field out for its default");
        assertOnlyProblem(withObject("{'type':'sphere','radius':null}"), "objects[0].radius",
                "must not be null; leave the field out for its default");
        assertOnlyProblem("{'lights':[{'type':'point','falloff':null}],'objects':[]}", "lights[0].falloff",
                "must not be null; leave the field out for its default");
    }

    @Test
    void rejectsNullObjectInList() {
        assertOnlyProblem("{'objects':[{'type':'sphere'},null]}", "objects[1]", "must be an object");
    }

    // --- numbers ---------------------------------------------------------------------------------

    @Test
    void rejectsNonFiniteNumbersAtTheirPaths() {
        List<FieldProblem> problems = problems(withObject("{'type':'sphere','center':[0,0,1e400],'radius':1e400}"));
        assertThat(problems).containsExactly(
                new FieldProblem("objects[0].center[2]", "must be a finite number"),
                new FieldProblem("objects[0].center[2]", "must be less than or equal to 1e12"),
                new FieldProblem("objects[0].radius", "must be a finite number"));
    }

    @Test
    void boundsEveryCoordinateByTheEnginesTestedRange() {
        assertOnlyProblem(withObject("{'type':'sphere','center':[0,0,1e300]}"), "objects[0].center[2]",
                "must be less than or equal to 1e12");
        assertOnlyProblem(withObject("{'type':'plane','point':[-1.000001e12,0,0]}"), "objects[0].point[0]",
                "must be greater than or equal to -1e12");
        assertOnlyProblem(withObject("{'type':'gltf','asset':'sha256-" + "0".repeat(64) + "','position':[0,2e12,0]}"),
                "objects[0].position[1]", "must be less than or equal to 1e12");
        assertOnlyProblem("{'camera':{'position':[0,0,5e12]},'objects':[]}", "camera.position[2]",
                "must be less than or equal to 1e12");
        assertOnlyProblem("{'lights':[{'type':'area','lookAt':[0,-3e12,0]}],'objects':[]}", "lights[0].lookAt[1]",
                "must be greater than or equal to -1e12");
        assertThatCode(() -> READER.read(json(withObject("{'type':'sphere','center':[1e12,-1e12,0]}"))))
                .doesNotThrowAnyException();
    }

    @Test
    void rejectsNegativeInfinityInCamera() {
        // infinity is also beyond the coordinates' bound, and both are said
        assertThat(problems("{'camera':{'position':[-1e999,0,0]},'objects':[]}")).containsExactly(
                new FieldProblem("camera.position[0]", "must be a finite number"),
                new FieldProblem("camera.position[0]", "must be greater than or equal to -1e12"));
    }

    @Test
    void rejectsNonFiniteAmbient() {
        List<FieldProblem> problems = problems("{'ambient':1e400,'objects':[]}");
        assertThat(problems).extracting(FieldProblem::field).containsOnly("ambient");
        assertThat(problems).extracting(FieldProblem::message).contains("must be a finite number");
    }

    // --- vectors ---------------------------------------------------------------------------------

    @Test
    void rejectsVectorOfTwoNumbers() {
        assertOnlyProblem(withObject("{'type':'sphere','center':[0,1]}"), "objects[0].center",
                "must be an array of three numbers [x, y, z]");
    }

    @Test
    void rejectsVectorOfFourNumbers() {
        assertOnlyProblem("{'camera':{'lookAt':[0,1,2,3]},'objects':[]}", "camera.lookAt",
                "must be an array of three numbers [x, y, z]");
    }

    @Test
    void rejectsNullVectorElement() {
        assertOnlyProblem(withObject("{'type':'sphere','center':[0,null,0]}"), "objects[0].center[1]",
                "must be a number");
    }

    @Test
    void rejectsNullElementInLightPosition() {
        assertOnlyProblem("{'lights':[{'type':'point','position':[null,1,1]}],'objects':[]}", "lights[0].position[0]",
                "must be a number");
    }

    // --- shapes ----------------------------------------------------------------------------------

    @Test
    void rejectsNegativeRadius() {
        assertOnlyProblem(withObject("{'type':'sphere','radius':-1}"), "objects[0].radius", "must be greater than 0");
    }

    @Test
    void rejectsZeroRadius() {
        assertOnlyProblem(withObject("{'type':'sphere','radius':0}"), "objects[0].radius", "must be greater than 0");
    }

    @Test
    void rejectsZeroBoxSizeComponent() {
        assertOnlyProblem("{'objects':[{'type':'sphere'},{'type':'box','size':[1,0,1]}]}", "objects[1].size[1]",
                "must be greater than 0");
    }

    @Test
    void rejectsNegativeBoxSizeComponent() {
        assertOnlyProblem(withObject("{'type':'box','size':[1,1,-2]}"), "objects[0].size[2]",
                "must be greater than 0");
    }

    @Test
    void rejectsZeroLengthPlaneNormal() {
        assertOnlyProblem(withObject("{'type':'plane','normal':[0,0,0]}"), "objects[0].normal",
                "must not be a zero-length vector");
    }

    @Test
    void rejectsZeroLengthCameraUp() {
        assertOnlyProblem("{'camera':{'up':[0,0,0]},'objects':[]}", "camera.up", "must not be a zero-length vector");
    }

    // --- colours ---------------------------------------------------------------------------------

    @ParameterizedTest
    @ValueSource(strings = {"red", "#fff", "#12345g", "#1234567", "123456", ""})
    void rejectsBackgroundNotRrggbb(String colour) {
        assertOnlyProblem("{'background':'" + colour + "','objects':[]}", "background",
                "must be a colour of the form #rrggbb");
    }

    @ParameterizedTest
    @ValueSource(strings = {"red", "#fff", "#12345g"})
    void rejectsMaterialColourNotRrggbb(String colour) {
        assertOnlyProblem(withObject("{'type':'sphere','material':{'type':'plastic','color':'" + colour + "'}}"),
                "objects[0].material.color", "must be a colour of the form #rrggbb");
    }

    @ParameterizedTest
    @ValueSource(strings = {"red", "#fff", "#12345g"})
    void rejectsLightColourNotRrggbb(String colour) {
        assertOnlyProblem("{'lights':[{'type':'point'},{'type':'point','color':'" + colour + "'}],'objects':[]}",
                "lights[1].color", "must be a colour of the form #rrggbb");
    }

    // --- camera, image, render -------------------------------------------------------------------

    @Test
    void rejectsZeroFov() {
        assertOnlyProblem("{'camera':{'fov':0},'objects':[]}", "camera.fov", "must be greater than 0");
    }

    @Test
    void rejectsFov180() {
        assertOnlyProblem("{'camera':{'fov':180},'objects':[]}", "camera.fov", "must be less than 180");
    }

    @Test
    void rejectsZeroWidth() {
        assertOnlyProblem("{'image':{'width':0},'objects':[]}", "image.width", "must be greater than 0");
    }

    @Test
    void rejectsNegativeWidth() {
        assertOnlyProblem("{'image':{'width':-800},'objects':[]}", "image.width", "must be greater than 0");
    }

    @Test
    void rejectsZeroHeight() {
        assertOnlyProblem("{'image':{'height':0},'objects':[]}", "image.height", "must be greater than 0");
    }

    @Test
    void rejectsQualityAboveOne() {
        assertOnlyProblem("{'image':{'quality':1.5},'objects':[]}", "image.quality",
                "must be less than or equal to 1");
    }

    @Test
    void rejectsUnknownImageFormat() {
        assertOnlyProblem("{'image':{'format':'gif'},'objects':[]}", "image.format", "must be \"jpg\" or \"png\"");
    }

    @Test
    void rejectsUnknownSampler() {
        assertOnlyProblem("{'render':{'sampler':'halton'},'objects':[]}", "render.sampler",
                "must be one of \"regular\", \"random\", \"jittered\", \"multijittered\", \"sobol\"");
    }

    @ParameterizedTest
    @ValueSource(strings = {"regular", "random", "jittered", "multijittered", "sobol"})
    void acceptsEverySamplerName(String sampler) {
        assertThatCode(() -> READER.read(json("{'render':{'sampler':'" + sampler + "'},'objects':[]}")))
                .doesNotThrowAnyException();
    }

    @ParameterizedTest
    @ValueSource(strings = {"0", "0.0", "0.02", "1", "1.0"})
    void acceptsAdaptiveThresholdsFromZeroToOne(String threshold) {
        SceneDto scene = READER.read(json("{'render':{'sampler':'sobol','adaptive':" + threshold + "},'objects':[]}"));
        assertThat(scene.render().adaptive()).isEqualTo(Double.parseDouble(threshold));
    }

    @Test
    void rejectsNegativeAdaptiveThreshold() {
        assertOnlyProblem("{'render':{'adaptive':-0.01},'objects':[]}", "render.adaptive",
                "must be greater than or equal to 0");
    }

    @Test
    void rejectsAdaptiveThresholdAboveOne() {
        assertOnlyProblem("{'render':{'adaptive':1.5},'objects':[]}", "render.adaptive",
                "must be less than or equal to 1");
    }

    @Test
    void rejectsNonFiniteAdaptiveThreshold() {
        List<FieldProblem> problems = problems("{'render':{'adaptive':1e400},'objects':[]}");
        assertThat(problems).extracting(FieldProblem::field).containsOnly("render.adaptive");
        assertThat(problems).extracting(FieldProblem::message).contains("must be a finite number");
    }

    @Test
    void rejectsAdaptiveThresholdThatIsNotANumber() {
        assertOnlyProblem("{'render':{'adaptive':'high'},'objects':[]}", "render.adaptive", "must be a number");
        assertOnlyProblem("{'render':{'adaptive':true},'objects':[]}", "render.adaptive", "must be a number");
    }

    @Test
    void rejectsZeroSamples() {
        assertOnlyProblem("{'render':{'samples':0},'objects':[]}", "render.samples", "must be greater than 0");
    }

    @Test
    void rejectsNegativeMaxDepth() {
        assertOnlyProblem("{'render':{'maxDepth':-1},'objects':[]}", "render.maxDepth",
                "must be greater than or equal to 0");
    }

    @Test
    void rejectsMaterialOverrideOutOfRange() {
        assertOnlyProblem(withObject("{'type':'sphere','material':{'type':'glass','ior':0.5}}"),
                "objects[0].material.ior", "must be greater than or equal to 1");
    }

    // --- version and name ------------------------------------------------------------------------

    @Test
    void refusesNewerVersion() {
        FieldProblem problem = onlyProblem("{'version':2,'objects':[]}", "version");
        assertThat(problem.message()).contains("newer").contains("version 1");
    }

    @Test
    void rejectsVersionZero() {
        assertOnlyProblem("{'version':0,'objects':[]}", "version", "must be 1 (the only scene format version there is)");
    }

    @Test
    void rejectsNameOver200Characters() {
        assertOnlyProblem("{'name':'" + "n".repeat(201) + "','objects':[]}", "name", "must be at most 200 characters");
    }

    @Test
    void acceptsNameOf200Characters() {
        assertThat(READER.read(json("{'name':'" + "n".repeat(200) + "','objects':[]}")).name()).hasSize(200);
    }

    // --- strict JSON: unknown fields and types ---------------------------------------------------

    @Test
    void rejectsUnknownMaterialFieldAndListsKnownFields() {
        FieldProblem problem = onlyProblem(withObject("{'type':'sphere','material':{'type':'chalk','colour':'#ffffff'}}"),
                "objects[0].material.colour");
        assertThat(problem.message()).startsWith("is not a field here").contains("color").contains("diffuse");
    }

    @Test
    void rejectsUnknownTopLevelField() {
        FieldProblem problem = onlyProblem("{'objects':[],'lookAt':[0,0,0]}", "lookAt");
        assertThat(problem.message()).contains("known fields").contains("camera").contains("objects");
    }

    @Test
    void rejectsOverrideAnotherMaterialKindUses() {
        FieldProblem problem = onlyProblem(withObject("{'type':'sphere','material':{'type':'chalk','ior':1.5}}"),
                "objects[0].material.ior");
        assertThat(problem.message()).startsWith("is not a field here");
    }

    @Test
    void rejectsUnknownObjectType() {
        FieldProblem problem = onlyProblem(withObject("{'type':'cone','radius':1}"), "objects[0].type");
        assertThat(problem.message()).contains("'cone'").contains("sphere, box, plane");
    }

    @Test
    void rejectsMissingObjectType() {
        FieldProblem problem = onlyProblem("{'objects':[{'type':'sphere'},{'radius':1}]}", "objects[1].type");
        assertThat(problem.message()).startsWith("is required").contains("sphere, box, plane");
    }

    @Test
    void rejectsUnknownMaterialType() {
        FieldProblem problem = onlyProblem(withObject("{'type':'sphere','material':{'type':'velvet'}}"),
                "objects[0].material.type");
        assertThat(problem.message()).contains("'velvet'").contains("flat, chalk, plastic, metal, mirror, glass");
    }

    @Test
    void rejectsUnknownLightType() {
        FieldProblem problem = onlyProblem("{'lights':[{'type':'spot'}],'objects':[]}", "lights[0].type");
        assertThat(problem.message()).contains("'spot'").contains("point");
    }

    // --- strict JSON: wrong value types ----------------------------------------------------------

    @Test
    void rejectsNumberGivenAsString() {
        assertOnlyProblem(withObject("{'type':'sphere','radius':'5'}"), "objects[0].radius", "must be a number");
    }

    @Test
    void rejectsFractionalWidth() {
        assertOnlyProblem("{'image':{'width':800.5},'objects':[]}", "image.width", "must be a whole number");
    }

    @Test
    void rejectsWidthBeyondIntRangeAsNumberNotAsMalformedJson() {
        assertOnlyProblem("{'image':{'width':10000000000},'objects':[]}", "image.width",
                "must be a whole number from -2147483648 to 2147483647");
    }

    @Test
    void rejectsSeedBeyondLongRange() {
        assertOnlyProblem("{'render':{'seed':99999999999999999999999},'objects':[]}", "render.seed",
                "must be a whole number from -9223372036854775808 to 9223372036854775807");
    }

    @Test
    void rejectsBooleanForNumber() {
        assertOnlyProblem("{'camera':{'fov':true},'objects':[]}", "camera.fov", "must be a number");
    }

    @Test
    void rejectsNumberForColour() {
        assertOnlyProblem("{'background':255,'objects':[]}", "background", "must be a string");
    }

    @Test
    void rejectsNumberForName() {
        assertOnlyProblem("{'name':123,'objects':[]}", "name", "must be a string");
    }

    @Test
    void rejectsBooleanForSampler() {
        assertOnlyProblem("{'render':{'sampler':true},'objects':[]}", "render.sampler", "must be a string");
    }

    @Test
    void rejectsHugeLightIntensity() {
        assertOnlyProblem("{'lights':[{'type':'point','intensity':1e308}],'objects':[]}", "lights[0].intensity",
                "must be less than or equal to 1e6");
    }

    @Test
    void rejectsObjectsGivenAsObject() {
        assertOnlyProblem("{'objects':{'type':'sphere'}}", "objects", "must be an array");
    }

    @Test
    void rejectsStringVectorElement() {
        assertOnlyProblem(withObject("{'type':'sphere','center':[0,'1',0]}"), "objects[0].center[1]",
                "must be a number");
    }

    // --- malformed bodies ------------------------------------------------------------------------

    @Test
    void rejectsMalformedJsonWithLineAndColumn() {
        // the object between whose fields the comma is missing
        FieldProblem problem = onlyProblem("{\n  'objects': [\n    {'type': 'sphere' 'radius': 1}\n  ]\n}", "objects[0]");
        assertThat(problem.message()).startsWith("malformed JSON").contains("line 3").contains("column");
    }

    @Test
    void rejectsTruncatedJsonWithLineAndColumn() {
        FieldProblem problem = onlyProblem("{'objects': [{'type': 'sphere',", "objects[0]");
        assertThat(problem.message()).startsWith("malformed JSON at line 1, column");
        assertThat(problem.message()).contains("the scene ends before every object and array in it is closed");
    }

    @Test
    void rejectsTrailingGarbage() {
        FieldProblem problem = onlyProblem("{'objects':[]} {'objects':[]}", "");
        assertThat(problem.message()).isEqualTo(
                "malformed JSON at line 1, column 16: unexpected content after the scene's closing '}'");
    }

    @Test
    void rejectsEmptyBody() {
        List<FieldProblem> problems = problems(new byte[0]);
        assertThat(problems).containsExactly(
                new FieldProblem("", "the request body is empty; expected a scene as a JSON object"));
    }

    @Test
    void rejectsWhitespaceOnlyBody() {
        assertThat(problems(json("  \n "))).extracting(FieldProblem::message)
                .containsExactly("the request body is empty; expected a scene as a JSON object");
    }

    @Test
    void rejectsArrayInsteadOfObject() {
        assertOnlyProblem("[{'objects':[]}]", "", "expected a scene as a JSON object, not array");
    }

    @Test
    void rejectsNullInsteadOfObject() {
        assertOnlyProblem("null", "", "expected a scene as a JSON object, not null");
    }

    @Test
    void rejectsDuplicateKeys() {
        FieldProblem problem = onlyProblem("{'name':'a','objects':[],'name':'b'}", "name");
        assertThat(problem.message()).startsWith("malformed JSON at line 1").contains("given twice");
    }

    @Test
    void rejectsDuplicateKeysInNestedObject() {
        FieldProblem problem = onlyProblem(withObject("{'type':'sphere','radius':1,'radius':2}"), "objects[0].radius");
        assertThat(problem.message()).contains("given twice");
    }

    // --- several problems at once ----------------------------------------------------------------

    @Test
    void reportsEveryValidationProblemSortedByField() {
        List<FieldProblem> problems = problems("""
                {'image':{'width':0,'height':-1},'background':'red',
                 'objects':[{'type':'sphere','radius':0},{'type':'plane','normal':[0,0,0]}]}
                """);
        assertThat(problems).extracting(FieldProblem::field)
                .containsExactly("background", "image.height", "image.width", "objects[0].radius", "objects[1].normal");
    }
}

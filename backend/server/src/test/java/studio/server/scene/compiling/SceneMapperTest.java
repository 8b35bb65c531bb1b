package studio.server.scene.compiling;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import studio.engine.light.AreaLight;
import studio.engine.light.Light;
import studio.engine.light.PointLight;
import studio.engine.light.SphereLight;
import studio.engine.math.Vec3;
import studio.engine.render.RenderSettings;
import studio.engine.sampler.JitteredSampler;
import studio.engine.sampler.RegularSampler;
import studio.engine.sampler.Sampler;
import studio.engine.sampler.SobolSampler;
import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.RenderDto;
import studio.server.scene.format.SceneDefaults;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;
import studio.server.scene.reading.SceneValidationTest;

/**
 * Defaults, configured limits and the rules that span fields, applied by {@link SceneMapper} after
 * the reader has validated a scene.
 */
class SceneMapperTest {

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader READER = new SceneReader(VALIDATION.getValidator());

    /** Small limits, so each can be crossed by a few characters of JSON. */
    private static final SceneLimits SMALL = new SceneLimits(64, 48, 9, 3, 2, 1, 100, 10_000);

    /** Render settings within {@link #SMALL}, for tests that cross another limit. */
    private static final String SMALL_RENDER = "'render':{'samples':1,'maxDepth':1},";

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    static CompiledScene map(String singleQuoted, SceneLimits limits) {
        return new SceneMapper(limits).map(READER.read(SceneValidationTest.json(singleQuoted)), 0);
    }

    static CompiledScene map(String singleQuoted) {
        return map(singleQuoted, SceneLimits.DEFAULTS);
    }

    static List<FieldProblem> problems(String singleQuoted, SceneLimits limits) {
        InvalidSceneException e = catchThrowableOfType(InvalidSceneException.class, () -> map(singleQuoted, limits));
        assertThat(e).as("expected the scene to be refused: %s", singleQuoted).isNotNull();
        return e.problems();
    }

    static FieldProblem onlyProblem(String singleQuoted, SceneLimits limits) {
        List<FieldProblem> problems = problems(singleQuoted, limits);
        assertThat(problems).hasSize(1);
        return problems.get(0);
    }

    // --- defaults --------------------------------------------------------------------------------

    @Test
    void fillsDefaultsForSceneOfOnlyObjects() {
        CompiledScene compiled = map("{'objects':[]}");
        RenderSettings settings = compiled.settings();
        assertThat(settings.width()).isEqualTo(800);
        assertThat(settings.height()).isEqualTo(600);
        assertThat(settings.sampler()).isEqualTo(new SobolSampler(16));
        assertThat(settings.maxDepth()).isEqualTo(6);
        assertThat(settings.seed()).isZero();
        assertThat(settings.adaptiveThreshold()).isEqualTo(SceneDefaults.ADAPTIVE).isEqualTo(0.05);
        assertThat(settings.adaptive()).isTrue();
        assertThat(settings.threads()).isZero();
        assertThat(compiled.format()).isEqualTo("png");
        assertThat(compiled.mediaType()).isEqualTo("image/png");
        assertThat(compiled.quality()).isEqualTo(0.92);
        assertThat(compiled.fileName()).isEqualTo("render.png");
        assertThat(compiled.scene().objectCount()).isZero();
        assertThat(compiled.scene().ambient()).isEqualTo(0.08);
        assertThat(compiled.scene().background()).isEqualTo(Colors.linear("#20232a"));
    }

    @Test
    void addsOneDefaultLightWhenLightsAreLeftOut() {
        List<Light> lights = map("{'objects':[]}").scene().lights();
        assertThat(lights).hasSize(1);
        PointLight light = (PointLight) lights.get(0);
        assertThat(light.position()).isEqualTo(new Vec3(5, 8, 5));
        assertThat(light.color()).isEqualTo(Colors.linear("#ffffff"));
        assertThat(light.intensity()).isEqualTo(1.0);
        assertThat(light.falloff()).isFalse();
    }

    @Test
    void aPointLightOfRadiusZeroIsThePointLightAndAboveZeroASphereLight() {
        assertThat(map("{'lights':[{'type':'point','position':[1,2,3],'radius':0}],'objects':[]}").scene().lights())
                .containsExactly(new PointLight(new Vec3(1, 2, 3), Colors.linear("#ffffff"), 1, false));
        assertThat(map("{'lights':[{'type':'point','position':[1,2,3],'radius':0.25,'falloff':true}],'objects':[]}")
                .scene().lights())
                .containsExactly(new SphereLight(new Vec3(1, 2, 3), 0.25, Colors.linear("#ffffff"), 1, true));
    }

    @Test
    void mapsAnAreaLightWithItsDefaults() {
        assertThat(map("{'lights':[{'type':'area','position':[0,3,0],'size':[2,0.5],'color':'#ff0000',"
                + "'intensity':4,'twoSided':true}],'objects':[]}").scene().lights())
                .containsExactly(new AreaLight(new Vec3(0, 3, 0), 2, 0.5, Vec3.ZERO, Colors.linear("#ff0000"), 4, false,
                        true));
        assertThat(map("{'lights':[{'type':'area'}],'objects':[]}").scene().lights())
                .containsExactly(new AreaLight(new Vec3(5, 8, 5), 1, 1, Vec3.ZERO, Colors.linear("#ffffff"), 1, false,
                        false));
    }

    @Test
    void emptyLightsMeansNoLights() {
        assertThat(map("{'lights':[],'objects':[]}").scene().lights()).isEmpty();
    }

    @Test
    void fillsDefaultsOfEachLightLeftPartlyOut() {
        List<Light> lights = map("{'lights':[{'type':'point','intensity':0.5,'falloff':true}],'objects':[]}")
                .scene().lights();
        assertThat(lights).containsExactly(
                new PointLight(new Vec3(5, 8, 5), Colors.linear("#ffffff"), 0.5, true));
    }

    @Test
    void keepsGivenSettings() {
        CompiledScene compiled = map("""
                {'name':'My Scene','image':{'width':32,'height':24,'format':'jpg','quality':0.5},
                 'render':{'sampler':'regular','samples':9,'maxDepth':2,'seed':42},
                 'objects':[{'type':'sphere'},{'type':'box'},{'type':'plane'}]}
                """);
        assertThat(compiled.settings().width()).isEqualTo(32);
        assertThat(compiled.settings().height()).isEqualTo(24);
        assertThat(compiled.settings().sampler()).isEqualTo(new RegularSampler(9));
        assertThat(compiled.settings().maxDepth()).isEqualTo(2);
        assertThat(compiled.settings().seed()).isEqualTo(42);
        assertThat(compiled.mediaType()).isEqualTo("image/jpeg");
        assertThat(compiled.quality()).isEqualTo(0.5);
        assertThat(compiled.fileName()).isEqualTo("My-Scene.jpg");
        assertThat(compiled.scene().objectCount()).isEqualTo(3);
    }

    @Test
    void passesThreadsToTheRenderSettings() {
        CompiledScene compiled = new SceneMapper(SceneLimits.DEFAULTS)
                .map(READER.read(SceneValidationTest.json("{'objects':[]}")), 3);
        assertThat(compiled.settings().threads()).isEqualTo(3);
    }

    @Test
    void appliesOverridesBeforeValidation() {
        SceneCompiler compiler = new SceneCompiler(READER, new SceneMapper(SceneLimits.DEFAULTS));
        CompiledScene compiled = compiler.compile(CompileRequest.of(SceneValidationTest.json("{'image':{'width':0},'objects':[]}")).overriding(Map.of("image.width", 20, "image.height", 10, "render.samples", 4)).onThreads(1));
        assertThat(compiled.settings().width()).isEqualTo(20);
        assertThat(compiled.settings().height()).isEqualTo(10);
        assertThat(compiled.settings().sampler().samplesPerPixel()).isEqualTo(4);
    }

    // --- limits ----------------------------------------------------------------------------------

    @Test
    void acceptsEverythingAtTheLimits() {
        CompiledScene compiled = map("""
                {'image':{'width':64,'height':48},'render':{'samples':9,'maxDepth':3},
                 'lights':[{'type':'point'}],'objects':[{'type':'sphere'},{'type':'plane'}]}
                """, SMALL);
        assertThat(compiled.scene().objectCount()).isEqualTo(2);
    }

    @Test
    void rejectsWidthOverLimit() {
        FieldProblem problem = onlyProblem("{'image':{'width':65,'height':48}," + SMALL_RENDER + "'objects':[]}", SMALL);
        assertThat(problem).isEqualTo(new FieldProblem("image.width", "must be at most 64 (this server's limit), not 65"));
    }

    @Test
    void rejectsDefaultWidthOverLimit() {
        List<FieldProblem> problems = problems("{" + SMALL_RENDER + "'objects':[]}", SMALL);
        assertThat(problems).extracting(FieldProblem::field).containsExactly("image.width", "image.height");
        assertThat(problems.get(0).message()).contains("64").contains("800");
    }

    @Test
    void rejectsHeightOverLimit() {
        FieldProblem problem = onlyProblem("{'image':{'width':64,'height':49}," + SMALL_RENDER + "'objects':[]}", SMALL);
        assertThat(problem).isEqualTo(new FieldProblem("image.height", "must be at most 48 (this server's limit), not 49"));
    }

    @Test
    void rejectsSamplesOverLimit() {
        FieldProblem problem = onlyProblem("{'image':{'width':8,'height':8},'render':{'samples':10,'maxDepth':3},'objects':[]}",
                SMALL);
        assertThat(problem).isEqualTo(new FieldProblem("render.samples", "must be at most 9 (this server's limit), not 10"));
    }

    @Test
    void rejectsDepthOverLimit() {
        FieldProblem problem = onlyProblem("{'image':{'width':8,'height':8},'render':{'samples':1,'maxDepth':4},"
                + "'objects':[]}", SMALL);
        assertThat(problem).isEqualTo(new FieldProblem("render.maxDepth", "must be at most 3 (this server's limit), not 4"));
    }

    @Test
    void rejectsObjectCountOverLimit() {
        FieldProblem problem = onlyProblem("{'image':{'width':8,'height':8}," + SMALL_RENDER
                + "'objects':[{'type':'sphere'},{'type':'sphere'},{'type':'sphere'}]}", SMALL);
        assertThat(problem).isEqualTo(new FieldProblem("objects", "has 3 objects; this server's limit is 2"));
    }

    @Test
    void rejectsLightCountOverLimit() {
        FieldProblem problem = onlyProblem("{'image':{'width':8,'height':8}," + SMALL_RENDER
                + "'lights':[{'type':'point'},{'type':'point'}],'objects':[]}", SMALL);
        assertThat(problem).isEqualTo(new FieldProblem("lights", "has 2 lights; this server's limit is 1"));
    }

    @Test
    void defaultLimitsAllowTheDefaultScene() {
        assertThat(SceneLimits.DEFAULTS.maxWidth()).isGreaterThanOrEqualTo(SceneDefaults.WIDTH);
        assertThat(SceneLimits.DEFAULTS.maxHeight()).isGreaterThanOrEqualTo(SceneDefaults.HEIGHT);
        assertThat(SceneLimits.DEFAULTS.maxSamples()).isGreaterThanOrEqualTo(SceneDefaults.SAMPLES);
        assertThat(SceneLimits.DEFAULTS.maxDepth()).isGreaterThanOrEqualTo(SceneDefaults.MAX_DEPTH);
    }

    // --- rules spanning fields -------------------------------------------------------------------

    @Test
    void rejectsRegularSamplerWithNonSquareSamples() {
        FieldProblem problem = onlyProblem("{'render':{'sampler':'regular','samples':10},'objects':[]}",
                SceneLimits.DEFAULTS);
        assertThat(problem.field()).isEqualTo("render.samples");
        assertThat(problem.message()).contains("square number").contains("10");
    }

    @Test
    void mapsEverySamplerNameOfTheEngine() {
        for (String name : Sampler.names()) {
            Sampler sampler = map("{'render':{'sampler':'" + name + "','samples':16},'objects':[]}").settings().sampler();
            assertThat(sampler).as(name).isEqualTo(Sampler.of(name, 16));
        }
    }

    @Test
    void samplerPatternOfTheSceneFormatListsExactlyTheEngineSamplers() {
        assertThat(List.of(RenderDto.SAMPLERS.split("\\|"))).isEqualTo(Sampler.names());
        for (String name : Sampler.names()) {
            assertThat(RenderDto.SAMPLERS_MESSAGE).contains("\"" + name + "\"");
        }
    }

    @Test
    void mapsTheAdaptiveThresholdToTheRenderSettings() {
        RenderSettings settings = map("{'render':{'sampler':'sobol','samples':64,'adaptive':0.05},'objects':[]}")
                .settings();
        assertThat(settings.adaptiveThreshold()).isEqualTo(0.05);
        assertThat(settings.adaptive()).isTrue();
        assertThat(settings.sampler()).isEqualTo(new SobolSampler(64));
        assertThat(map("{'render':{'adaptive':0},'objects':[]}").settings().adaptive()).isFalse();
    }

    @Test
    void rejectsAdaptiveSamplingWithTheRegularSampler() {
        FieldProblem problem = onlyProblem("{'render':{'sampler':'regular','samples':16,'adaptive':0.1},'objects':[]}",
                SceneLimits.DEFAULTS);
        assertThat(problem.field()).isEqualTo("render.adaptive");
        assertThat(problem.message()).contains("regular sampler");
        assertThat(map("{'render':{'sampler':'regular','samples':16,'adaptive':0},'objects':[]}").settings().sampler())
                .isEqualTo(new RegularSampler(16));
    }

    @Test
    void adaptiveSamplingIsOnByDefaultWithSobolOnly() {
        assertThat(map("{'render':{'sampler':'sobol'},'objects':[]}").settings().adaptiveThreshold())
                .isEqualTo(SceneDefaults.ADAPTIVE);
        assertThat(map("{'render':{'sampler':'jittered'},'objects':[]}").settings().adaptive()).isFalse();
        assertThat(map("{'render':{'sampler':'jittered','adaptive':0.1},'objects':[]}").settings().adaptiveThreshold())
                .isEqualTo(0.1);
        RenderSettings regular = map("{'render':{'sampler':'regular','samples':16},'objects':[]}").settings();
        assertThat(regular.adaptive()).isFalse();
        assertThat(regular.sampler()).isEqualTo(new RegularSampler(16));
    }

    @Test
    void acceptsJitteredSamplerWithAnySampleCount() {
        assertThat(map("{'render':{'sampler':'jittered','samples':10},'objects':[]}").settings().sampler())
                .isEqualTo(new JitteredSampler(10));
    }

    @Test
    void rejectsCameraUpParallelToViewDirection() {
        FieldProblem problem = onlyProblem(
                "{'camera':{'position':[0,5,0],'lookAt':[0,0,0],'up':[0,1,0]},'objects':[]}", SceneLimits.DEFAULTS);
        assertThat(problem.field()).isEqualTo("camera.up");
        assertThat(problem.message()).contains("parallel to the view direction");
    }

    @Test
    void rejectsCameraUpAntiParallelToViewDirection() {
        FieldProblem problem = onlyProblem(
                "{'camera':{'position':[1,2,3],'lookAt':[1,2,-7],'up':[0,0,2.5]},'objects':[]}", SceneLimits.DEFAULTS);
        assertThat(problem.field()).isEqualTo("camera.up");
    }

    @Test
    void rejectsDefaultUpWhenLookingStraightDown() {
        FieldProblem problem = onlyProblem("{'camera':{'position':[0,10,0]},'objects':[]}", SceneLimits.DEFAULTS);
        assertThat(problem.field()).isEqualTo("camera.up");
    }

    @Test
    void acceptsCameraUpNearlyParallelToViewDirection() {
        assertThat(map("{'camera':{'position':[0,5,0],'lookAt':[0,0,0],'up':[0.001,1,0]},'objects':[]}").scene()
                .camera()).isNotNull();
    }

    @Test
    void rejectsLookAtEqualToPosition() {
        FieldProblem problem = onlyProblem("{'camera':{'position':[1,2,3],'lookAt':[1,2,3]},'objects':[]}",
                SceneLimits.DEFAULTS);
        assertThat(problem).isEqualTo(new FieldProblem("camera.lookAt", "must differ from camera.position"));
    }

    @Test
    void rejectsAnAreaLightAimedAtItsOwnPosition() {
        FieldProblem problem = onlyProblem("{'lights':[{'type':'point'},{'type':'area','position':[1,2,3],"
                + "'lookAt':[1,2,3]}],'objects':[]}", SceneLimits.DEFAULTS);
        assertThat(problem).isEqualTo(new FieldProblem("lights[1].lookAt", "must differ from lights[1].position"));
        // lookAt left out is the origin; -0.0 names the same point
        FieldProblem byDefault = onlyProblem("{'lights':[{'type':'area','position':[0,-0.0,0]}],'objects':[]}",
                SceneLimits.DEFAULTS);
        assertThat(byDefault).isEqualTo(new FieldProblem("lights[0].lookAt", "must differ from lights[0].position"));
    }

    @Test
    void rejectsLookAtThatDiffersFromPositionOnlyInTheSignOfZero() {
        FieldProblem problem = onlyProblem("{'camera':{'position':[0,2,3],'lookAt':[-0.0,2,3]},'objects':[]}",
                SceneLimits.DEFAULTS);
        assertThat(problem).isEqualTo(new FieldProblem("camera.lookAt", "must differ from camera.position"));
    }

    @Test
    void reportsEveryMappingProblemTogether() {
        List<FieldProblem> problems = problems("""
                {'image':{'width':65,'height':49},'render':{'sampler':'regular','samples':10,'maxDepth':4},
                 'camera':{'position':[0,0,0],'lookAt':[0,0,0]},
                 'lights':[{'type':'point'},{'type':'point'}],
                 'objects':[{'type':'sphere'},{'type':'sphere'},{'type':'sphere'}]}
                """, SMALL);
        assertThat(problems).extracting(FieldProblem::field).containsExactlyInAnyOrder(
                "image.width", "image.height", "render.samples", "render.maxDepth", "render.samples", "objects",
                "lights", "camera.lookAt");
    }

    @Test
    void exceptionMessageListsEveryProblem() {
        InvalidSceneException e = catchThrowableOfType(InvalidSceneException.class,
                () -> map("{'image':{'width':65,'height':49}," + SMALL_RENDER + "'objects':[]}", SMALL));
        assertThat(e.getMessage()).isEqualTo("image.width: must be at most 64 (this server's limit), not 65; "
                + "image.height: must be at most 48 (this server's limit), not 49");
    }
}

package studio.server.api;

import static org.assertj.core.api.Assertions.assertThat;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.webmvc.test.autoconfigure.AutoConfigureMockMvc;
import org.springframework.test.web.servlet.MockMvc;

import com.networknt.schema.Error;
import com.networknt.schema.Schema;
import com.networknt.schema.SchemaRegistry;
import com.networknt.schema.SpecificationVersion;

import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.examples.ExampleSceneFiles;
import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;
import tools.jackson.databind.DeserializationFeature;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ObjectNode;

/**
 * The published Scene schema (components/schemas/Scene of /v3/api-docs, checked by a JSON Schema
 * 2020-12 validator) and the server (its SceneCompiler, as POST /api/render and /api/jobs use it)
 * agree: both accept every example scene, both refuse each kind of invalid scene, and the rules
 * JSON Schema cannot state are listed here, each one accepted by the schema and refused by the
 * server at the field it names.
 */
@SpringBootTest(properties = {
        "studio.limits.max-width=1024", "studio.limits.max-height=1024", "studio.limits.max-samples=64",
        "studio.limits.max-depth=16", "studio.limits.max-objects=30", "studio.limits.max-lights=8",
        "studio.limits.max-triangles=5000", "studio.limits.max-pixel-samples=16777216"})
@AutoConfigureMockMvc
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class SceneContractAgreementTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    /** Reads 1e400 as the number it is in JSON (a double would be infinite, which the validator takes for no number). */
    private static final JsonMapper NUMBERS_AS_WRITTEN = JsonMapper.builder()
            .enable(DeserializationFeature.USE_BIG_DECIMAL_FOR_FLOATS).build();
    private static final String TRIANGLE = "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\n";

    @Autowired
    MockMvc mvc;

    @Autowired
    SceneCompiler compiler;

    private Schema sceneSchema;

    /** The Scene schema exactly as published, its $refs resolved within the OpenAPI document's components. */
    @BeforeAll
    void loadPublishedSchema() throws Exception {
        JsonNode doc = JSON.readTree(mvc.perform(get("/v3/api-docs")).andExpect(status().isOk()).andReturn()
                .getResponse().getContentAsByteArray());
        ObjectNode wrapper = JSON.createObjectNode();
        wrapper.put("$schema", "https://json-schema.org/draft/2020-12/schema");
        wrapper.put("$ref", "#/components/schemas/Scene");
        wrapper.set("components", doc.get("components"));
        sceneSchema = SchemaRegistry.withDefaultDialect(SpecificationVersion.DRAFT_2020_12).getSchema(wrapper);
    }

    // --- the cases -------------------------------------------------------------------------------

    /** scenes/*.json and scenes/bench/*.json. */
    static Stream<Path> exampleScenes() throws IOException {
        try (Stream<Path> bench = Files.list(ExampleSceneFiles.dir().resolve("bench"))) {
            List<Path> benchScenes = bench.filter(p -> p.toString().endsWith(".json")).sorted().toList();
            assertThat(benchScenes).isNotEmpty();
            return Stream.concat(ExampleSceneFiles.all().stream(), benchScenes.stream());
        }
    }

    /** Valid scenes at the edges of the rules. */
    static Stream<Arguments> edgeScenes() {
        return Stream.of(
                edge("coordinates at the bound", "{'camera':{'position':[1e12,0,0],'lookAt':[-1e12,0,0]},"
                        + "'lights':[{'type':'point','position':[0,1e12,0]}],'objects':[{'type':'sphere','center':[0,0,-1e12]}]}"),
                edge("every limit reached", "{'image':{'width':1024,'height':1024},'render':{'samples':16,'maxDepth':16},"
                        + "'lights':[" + repeat("{'type':'point'}", 8) + "],'objects':[" + repeat("{'type':'sphere'}", 30)
                        + "]}"),
                edge("the most samples a pixel may take", "{'image':{'width':512,'height':512},'render':{'samples':64},"
                        + "'objects':[]}"),
                edge("no lights", "{'lights':[],'objects':[]}"),
                edge("a name of 200 characters outside the BMP", "{'name':'" + "\uD83D\uDE00".repeat(200)
                        + "','objects':[]}"),
                edge("the smallest seed", "{'render':{'seed':-9223372036854775808},'objects':[]}"),
                edge("the largest seed", "{'render':{'seed':9223372036854775807},'objects':[]}"),
                edge("the regular sampler with a square number of samples and no adaptive sampling",
                        "{'render':{'sampler':'regular','samples':9,'adaptive':0},'objects':[]}"),
                edge("adaptive sampling at its bounds", "{'image':{'width':64,'height':64},"
                        + "'render':{'sampler':'random','samples':64,'adaptive':1},'objects':[]}"),
                edge("a mesh file this server ships", object("{'type':'mesh','file':'meshes/torus-knot.obj'}")),
                edge("an inline mesh, scaled and rotated", object("{'type':'mesh','obj':'" + TRIANGLE
                        + "','scale':0.5,'rotation':[0,90,0],'position':[1,2,3]}")),
                edge("a tiny but non-zero plane normal", object("{'type':'plane','normal':[1e-300,-0.0,0]}")),
                edge("a field of view just under 180", "{'camera':{'fov':179.9},'objects':[]}"),
                edge("upper-case colours", "{'background':'#ABCDEF','objects':[]}"),
                edge("every material override at its bounds", "{'objects':["
                        + "{'type':'sphere','material':{'type':'flat','color':'#000000'}},"
                        + "{'type':'sphere','material':{'type':'chalk','diffuse':0}},"
                        + "{'type':'sphere','material':{'type':'plastic','diffuse':1,'specular':0,'shininess':1}},"
                        + "{'type':'sphere','material':{'type':'metal','shininess':10000,'reflectivity':1}},"
                        + "{'type':'sphere','material':{'type':'mirror','reflectivity':0}},"
                        + "{'type':'sphere','material':{'type':'glass','ior':4,'specular':1}}]}"),
                edge("a light at the largest intensity with fall-off",
                        "{'lights':[{'type':'point','intensity':1e6,'falloff':true}],'objects':[]}"),
                edge("JPEG at quality 0", "{'image':{'format':'jpg','quality':0},'objects':[]}"),
                edge("objects and lights named by the editor, up to 200 characters",
                        "{'lights':[{'type':'point','name':'key light'}],'objects':[{'type':'sphere','name':'ball'},"
                                + "{'type':'box','name':''},{'type':'plane','name':'floor'},"
                                + "{'type':'mesh','file':'meshes/torus-knot.obj','name':'" + "\uD83D\uDE00".repeat(200) + "'}]}"));
    }

    /** One scene per kind of violation: (what is wrong, the scene with single quotes, the field the server names). */
    static Stream<Arguments> invalidScenes() {
        return Stream.of(
                // structure and required fields
                invalid("not an object", "['objects']", ""),
                // coordinates: at most 1e12 m from the origin (Coordinates), infinity included
                invalid("a coordinate beyond 1e12", object("{'type':'sphere','center':[0,1e300,0]}"), "objects[0].center[1]"),
                invalid("a camera target below -1e12", "{'camera':{'lookAt':[0,0,-2e12]},'objects':[]}", "camera.lookAt[2]"),
                invalid("a number beyond double range (1e400)", object("{'type':'sphere','center':[0,1e400,0]}"),
                        "objects[0].center[1]"),
                invalid("objects missing", "{'name':'x'}", "objects"),
                invalid("objects not an array", "{'objects':{'type':'sphere'}}", "objects"),
                invalid("an object that is null", "{'objects':[null]}", "objects[0]"),
                invalid("object type missing", object("{'radius':1}"), "objects[0].type"),
                invalid("unknown object type", object("{'type':'cone'}"), "objects[0].type"),
                invalid("unknown top-level field", "{'objects':[],'lookAt':[0,0,0]}", "lookAt"),
                invalid("field of another object kind", object("{'type':'sphere','size':[1,1,1]}"), "objects[0].size"),
                invalid("an explicit null for a defaulted field", "{'image':null,'objects':[]}", "image"),
                invalid("an explicit null for a number", object("{'type':'sphere','radius':null}"), "objects[0].radius"),
                // wrong JSON types
                invalid("number as a string", object("{'type':'sphere','radius':'1'}"), "objects[0].radius"),
                invalid("string given a number", "{'name':123,'objects':[]}", "name"),
                invalid("number given a boolean", "{'ambient':true,'objects':[]}", "ambient"),
                invalid("boolean given a number", "{'lights':[{'type':'point','falloff':1}],'objects':[]}",
                        "lights[0].falloff"),
                invalid("fraction for a whole number", "{'image':{'width':64.5},'objects':[]}", "image.width"),
                invalid("seed beyond the 64-bit range", "{'render':{'seed':9223372036854775808},'objects':[]}",
                        "render.seed"),
                // vectors
                invalid("vector of two", object("{'type':'sphere','center':[0,1]}"), "objects[0].center"),
                invalid("vector of four", "{'camera':{'lookAt':[0,1,2,3]},'objects':[]}", "camera.lookAt"),
                invalid("vector with a null", object("{'type':'sphere','center':[0,null,0]}"), "objects[0].center[1]"),
                invalid("vector with a string", object("{'type':'sphere','center':[0,'1',0]}"), "objects[0].center[1]"),
                invalid("zero plane normal", object("{'type':'plane','normal':[0,0,0]}"), "objects[0].normal"),
                invalid("zero camera up", "{'camera':{'up':[0,0,0]},'objects':[]}", "camera.up"),
                // ranges
                invalid("zero radius", object("{'type':'sphere','radius':0}"), "objects[0].radius"),
                invalid("negative box size", object("{'type':'box','size':[1,1,-2]}"), "objects[0].size[2]"),
                invalid("zero mesh scale", object("{'type':'mesh','obj':'" + TRIANGLE + "','scale':0}"),
                        "objects[0].scale"),
                invalid("field of view 180", "{'camera':{'fov':180},'objects':[]}", "camera.fov"),
                invalid("ambient above 1", "{'ambient':1.5,'objects':[]}", "ambient"),
                invalid("zero width", "{'image':{'width':0},'objects':[]}", "image.width"),
                invalid("JPEG quality above 1", "{'image':{'quality':1.5},'objects':[]}", "image.quality"),
                invalid("zero samples", "{'render':{'samples':0},'objects':[]}", "render.samples"),
                invalid("negative maxDepth", "{'render':{'maxDepth':-1},'objects':[]}", "render.maxDepth"),
                invalid("adaptive threshold above 1", "{'render':{'adaptive':1.5},'objects':[]}", "render.adaptive"),
                invalid("version 2", "{'version':2,'objects':[]}", "version"),
                invalid("name over 200 characters", "{'name':'" + "n".repeat(201) + "','objects':[]}", "name"),
                invalid("an object's name over 200 characters", object("{'type':'sphere','name':'" + "n".repeat(201) + "'}"),
                        "objects[0].name"),
                invalid("a light's name that is not a string", "{'lights':[{'type':'point','name':7}],'objects':[]}",
                        "lights[0].name"),
                invalid("light intensity above 1e6", "{'lights':[{'type':'point','intensity':2e6}],'objects':[]}",
                        "lights[0].intensity"),
                invalid("negative light intensity", "{'lights':[{'type':'point','intensity':-1}],'objects':[]}",
                        "lights[0].intensity"),
                // this server's limits
                invalid("width over the limit", "{'image':{'width':1025},'objects':[]}", "image.width"),
                invalid("height over the limit", "{'image':{'height':1025},'objects':[]}", "image.height"),
                invalid("samples over the limit", "{'render':{'samples':65},'objects':[]}", "render.samples"),
                invalid("maxDepth over the limit", "{'render':{'maxDepth':17},'objects':[]}", "render.maxDepth"),
                invalid("more objects than the limit", "{'objects':[" + repeat("{'type':'sphere'}", 31) + "]}",
                        "objects"),
                invalid("more lights than the limit", "{'lights':[" + repeat("{'type':'point'}", 9) + "],'objects':[]}",
                        "lights"),
                // names and colours
                invalid("colour without #", "{'background':'ffffff','objects':[]}", "background"),
                invalid("colour of three digits", object("{'type':'sphere','material':{'type':'flat','color':'#fff'}}"),
                        "objects[0].material.color"),
                invalid("colour with a non-hex digit", "{'lights':[{'type':'point','color':'#12345g'}],'objects':[]}",
                        "lights[0].color"),
                invalid("colour name", "{'background':'red','objects':[]}", "background"),
                invalid("unknown image format", "{'image':{'format':'gif'},'objects':[]}", "image.format"),
                invalid("unknown sampler", "{'render':{'sampler':'halton'},'objects':[]}", "render.sampler"),
                // materials
                invalid("material type missing", object("{'type':'sphere','material':{'color':'#ffffff'}}"),
                        "objects[0].material.type"),
                invalid("unknown material type", object("{'type':'sphere','material':{'type':'velvet'}}"),
                        "objects[0].material.type"),
                invalid("override of another material kind", object("{'type':'sphere','material':{'type':'mirror','ior':1.5}}"),
                        "objects[0].material.ior"),
                invalid("diffuse above 1", object("{'type':'sphere','material':{'type':'chalk','diffuse':2}}"),
                        "objects[0].material.diffuse"),
                invalid("glass ior below 1", object("{'type':'sphere','material':{'type':'glass','ior':0.5}}"),
                        "objects[0].material.ior"),
                invalid("shininess below 1", object("{'type':'box','material':{'type':'plastic','shininess':0}}"),
                        "objects[0].material.shininess"),
                invalid("reflectivity below 0", object("{'type':'box','material':{'type':'metal','reflectivity':-0.1}}"),
                        "objects[0].material.reflectivity"),
                // lights
                invalid("unknown light type", "{'lights':[{'type':'spot'}],'objects':[]}", "lights[0].type"),
                invalid("a light that is null", "{'lights':[null],'objects':[]}", "lights[0]"),
                // meshes and samplers: rules across fields that the schema states too
                invalid("mesh with neither obj nor file", object("{'type':'mesh'}"), "objects[0]"),
                invalid("mesh with both obj and file",
                        object("{'type':'mesh','obj':'" + TRIANGLE + "','file':'meshes/torus-knot.obj'}"), "objects[0]"),
                invalid("mesh with an asset id in capitals",
                        object("{'type':'mesh','asset':'sha256-" + "AB".repeat(32) + "'}"), "objects[0].asset"),
                invalid("mesh with both file and asset", object("{'type':'mesh','file':'meshes/torus-knot.obj',"
                        + "'asset':'sha256-" + "ab".repeat(32) + "'}"), "objects[0]"),
                invalid("mesh file outside the folder", object("{'type':'mesh','file':'../secret.obj'}"),
                        "objects[0].file"),
                invalid("regular sampler with a non-square number of samples",
                        "{'render':{'sampler':'regular','samples':8},'objects':[]}", "render.samples"),
                invalid("adaptive sampling with the regular sampler",
                        "{'render':{'sampler':'regular','samples':16,'adaptive':0.1},'objects':[]}", "render.adaptive"));
    }

    /**
     * Rules JSON Schema cannot state: the schema accepts these scenes and the server refuses them,
     * naming the field. (Duplicate keys: a JSON Schema validator sees only one of them.)
     */
    static Stream<Arguments> beyondTheSchema() {
        String parallelUp = "{'camera':{'position':[0,5,0],'lookAt':[0,0,0],'up':[0,1,0]},'objects':[]}";
        return Stream.of(
                invalid("camera up parallel to the view direction", parallelUp, "camera.up"),
                invalid("camera looking at its own position",
                        "{'camera':{'position':[1,2,3],'lookAt':[1,2,3]},'objects':[]}", "camera.lookAt"),
                invalid("OBJ text that does not parse", object("{'type':'mesh','obj':'v 0 0 zero\\nf 1 2 3\\n'}"),
                        "objects[0].obj"),
                invalid("OBJ face naming a vertex that does not exist", object("{'type':'mesh','obj':'v 0 0 0\\nf 1 2 3\\n'}"),
                        "objects[0].obj"),
                invalid("degenerate mesh: no triangle with an area",
                        object("{'type':'mesh','obj':'v 0 0 0\\nv 1 0 0\\nv 2 0 0\\nf 1 2 3\\n'}"), "objects[0]"),
                invalid("mesh vertices beyond double range once scaled",
                        object("{'type':'mesh','obj':'v 0 0 0\\nv 1e300 0 0\\nv 0 1 0\\nf 1 2 3\\n','scale':1e300}"),
                        "objects[0]"),
                invalid("mesh file this server does not ship", object("{'type':'mesh','file':'meshes/nope.obj'}"),
                        "objects[0].file"),
                invalid("mesh asset this server does not keep", object("{'type':'mesh','asset':'sha256-"
                        + "ab".repeat(32) + "'}"), "objects[0].asset"),
                invalid("more triangles than the limit, all meshes together", "{'objects':["
                        + "{'type':'mesh','obj':'" + fan(2600) + "'},{'type':'mesh','obj':'" + fan(2600) + "'}]}",
                        "objects[1].obj"),
                invalid("a whole number written with a fraction part (64.0)", "{'image':{'width':64.0},'objects':[]}",
                        "image.width"),
                invalid("width x height x samples over the render budget, each within its limit",
                        "{'image':{'width':1024,'height':1024},'render':{'samples':17},'objects':[]}", "render.samples"),
                invalid("a duplicate key", "{'name':'a','name':'b','objects':[]}", "name"));
    }

    // --- the tests -------------------------------------------------------------------------------

    @ParameterizedTest(name = "{0}")
    @MethodSource("exampleScenes")
    void bothAcceptEveryExampleScene(Path file) throws IOException {
        byte[] scene = Files.readAllBytes(file);
        assertThat(schemaErrors(scene)).as("schema errors").isEmpty();
        assertThat(serverProblems(scene)).as("server problems").isEmpty();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("edgeScenes")
    void bothAcceptScenesAtTheEdgesOfTheRules(String edge, String scene) {
        byte[] json = json(scene);
        assertThat(schemaErrors(json)).as("schema errors").isEmpty();
        assertThat(serverProblems(json)).as("server problems").isEmpty();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("invalidScenes")
    void bothRejectEachKindOfInvalidScene(String violation, String scene, String field) {
        byte[] json = json(scene);
        assertThat(schemaErrors(json)).as("the schema refuses it").isNotEmpty();
        assertThat(serverProblems(json)).as("the server refuses it").extracting(FieldProblem::field).contains(field);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("beyondTheSchema")
    void schemaAcceptsWhatOnlyTheServerCanRefuse(String rule, String scene, String field) {
        byte[] json = json(scene);
        assertThat(schemaErrors(json)).as("the schema accepts it").isEmpty();
        assertThat(serverProblems(json)).as("the server refuses it").extracting(FieldProblem::field).contains(field);
    }

    // --- helpers -------------------------------------------------------------------------------

    private List<String> schemaErrors(byte[] scene) {
        List<Error> errors = sceneSchema.validate(NUMBERS_AS_WRITTEN.readTree(scene));
        return errors.stream().map(Error::toString).toList();
    }

    private List<FieldProblem> serverProblems(byte[] scene) {
        try {
            compiler.compile(CompileRequest.of(scene));
            return List.of();
        } catch (InvalidSceneException e) {
            return e.problems();
        }
    }

    private static Arguments edge(String what, String scene) {
        return Arguments.of(what, scene);
    }

    private static Arguments invalid(String what, String scene, String field) {
        return Arguments.of(what, scene, field);
    }

    private static String object(String object) {
        return "{'objects':[" + object + "]}";
    }

    private static String repeat(String item, int times) {
        return IntStream.range(0, times).mapToObj(i -> item).collect(Collectors.joining(","));
    }

    /** OBJ text of a fan of {@code triangles} triangles around the origin. */
    private static String fan(int triangles) {
        StringBuilder obj = new StringBuilder("v 0 0 0\\n");
        for (int i = 0; i <= triangles; i++) {
            double a = 2 * Math.PI * i / (triangles + 1);
            obj.append("v ").append(Math.cos(a)).append(' ').append(Math.sin(a)).append(" 0\\n");
        }
        for (int i = 0; i < triangles; i++) {
            obj.append("f 1 ").append(i + 2).append(' ').append(i + 3).append("\\n");
        }
        return obj.toString();
    }

    private static byte[] json(String singleQuoted) {
        return singleQuoted.replace('\'', '"').getBytes(StandardCharsets.UTF_8);
    }
}

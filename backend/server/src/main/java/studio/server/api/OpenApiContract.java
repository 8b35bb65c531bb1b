package studio.server.api;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.springdoc.core.customizers.OpenApiCustomizer;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

import com.fasterxml.jackson.core.JsonProcessingException;

import io.swagger.v3.core.util.Json31;
import io.swagger.v3.oas.models.Components;
import io.swagger.v3.oas.models.OpenAPI;
import io.swagger.v3.oas.models.Operation;
import io.swagger.v3.oas.models.PathItem;
import io.swagger.v3.oas.models.headers.Header;
import io.swagger.v3.oas.models.info.Info;
import io.swagger.v3.oas.models.links.Link;
import io.swagger.v3.oas.models.media.Content;
import io.swagger.v3.oas.models.media.MediaType;
import io.swagger.v3.oas.models.media.Schema;
import io.swagger.v3.oas.models.parameters.Parameter;
import io.swagger.v3.oas.models.parameters.RequestBody;
import io.swagger.v3.oas.models.responses.ApiResponse;
import io.swagger.v3.oas.models.responses.ApiResponses;
import io.swagger.v3.oas.models.security.SecurityRequirement;
import io.swagger.v3.oas.models.security.SecurityScheme;

import studio.server.scene.format.SceneLimits;
import studio.server.scene.format.SceneMediaTypes;

/**
 * The API's OpenAPI 3.1 document (/v3/api-docs, Swagger UI at /swagger-ui.html). springdoc finds
 * the operations and their parameters in the controllers; this adds what it cannot know: the scene
 * format as the request body (the schema the server validates with, with its limits), and every
 * response with its status, media type and headers. An operation named here that the controllers
 * no longer have fails the document, so the contract cannot silently drift. Every /api operation may
 * answer 401 when sign-in is on (docs/security.md): the bearer scheme is optional, as sign-in is.
 */
@Configuration(proxyBeanMethods = false)
class OpenApiContract {

    static final String PROBLEM_JSON = "application/problem+json";

    @Bean
    OpenApiCustomizer studioContract(SceneLimits limits) {
        return openApi -> describe(openApi, limits);
    }

    static void describe(OpenAPI api, SceneLimits limits) {
        api.info(new Info().title("Ray Studio").version("1").description(
                "Scenes in, ray-traced images out. Every error is an RFC 9457 problem (application/problem+json); "
                        + "an invalid scene is a 400 whose `errors` name each bad field by its JSON path. "
                        + "With sign-in on, every /api request sends `Authorization: Bearer` with an API key or a JWT; "
                        + "a job is seen only by the principal that started it."));
        components(api, limits);
        // sign-in is off by default (no requirement), on with one property (the bearer scheme)
        api.addSecurityItem(new SecurityRequirement()).addSecurityItem(new SecurityRequirement().addList(BEARER));

        operation(api, "/api/render", PathItem.HttpMethod.POST, "render", "renderScene",
                "Render a scene and return the image")
                .requestBody(sceneBody())
                .responses(new ApiResponses()
                        .addApiResponse("200", image("The rendered image, PNG or JPEG as the scene's image.format says"))
                        .addApiResponse("400", ref("InvalidScene"))
                        .addApiResponse("408", ref("BodyTooSlow"))
                        .addApiResponse("413", ref("BodyTooLarge"))
                        .addApiResponse("415", ref("NotJson"))
                        .addApiResponse("422", ref("RenderTimeExceeded"))
                        .addApiResponse("503", ref("RenderBusy")));
        operation(api, "/api/jobs", PathItem.HttpMethod.POST, "jobs", "startJob", "Start a render job")
                .requestBody(sceneBody())
                .responses(new ApiResponses()
                        .addApiResponse("202", jobStatus("Queued; Location names the job")
                                .addHeaderObject("Location", headerRef("Location"))
                                .link("status", jobLink("getJob"))
                                .link("events", jobLink("streamJobEvents"))
                                .link("image", jobLink("getJobImage"))
                                .link("cancel", jobLink("cancelJob")))
                        .addApiResponse("400", ref("InvalidScene"))
                        .addApiResponse("408", ref("BodyTooSlow"))
                        .addApiResponse("413", ref("BodyTooLarge"))
                        .addApiResponse("415", ref("NotJson"))
                        .addApiResponse("429", ref("QueueFull"))
                        .addApiResponse("503", ref("MemoryBusy")));
        operation(api, "/api/jobs/{id}", PathItem.HttpMethod.GET, "jobs", "getJob", "A job's status")
                .responses(new ApiResponses()
                        .addApiResponse("200", jobStatus("The job's status"))
                        .addApiResponse("404", ref("JobNotFound")));
        operation(api, "/api/jobs/{id}", PathItem.HttpMethod.DELETE, "jobs", "cancelJob",
                "Cancel a job: a queued one at once, a running one within a few milliseconds")
                .responses(new ApiResponses()
                        .addApiResponse("202", jobStatus("The job's status after the cancel"))
                        .addApiResponse("404", ref("JobNotFound")));
        operation(api, "/api/jobs/{id}/events", PathItem.HttpMethod.GET, "jobs", "streamJobEvents",
                "A job's progress as server-sent events")
                .responses(new ApiResponses()
                        .addApiResponse("200", new ApiResponse().description("Events `status` (a JobStatus, on every "
                                + "state change), `tile` ({x, y, width, height, png: base64, progress} for every finished "
                                + "tile; a late client first gets the tiles so far) and `end` (the final JobStatus); "
                                + "then the stream closes")
                                .content(new Content().addMediaType("text/event-stream",
                                        new MediaType().schema(schemaRef("JobEvent")))))
                        .addApiResponse("404", ref("JobNotFound")));
        operation(api, "/api/jobs/{id}/image", PathItem.HttpMethod.GET, "jobs", "getJobImage",
                "A finished job's image")
                .responses(new ApiResponses()
                        .addApiResponse("200", image("The image"))
                        .addApiResponse("404", ref("JobNotFound"))
                        .addApiResponse("409", ref("JobNotDone")));
        operation(api, "/api/scenes", PathItem.HttpMethod.GET, "scenes", "listScenes", "The example scenes")
                .responses(new ApiResponses().addApiResponse("200", json("The examples' names",
                        schema("{\"type\": \"array\", \"items\": {\"$ref\": \"" + ApiSchemas.REF + "SceneSummary\"}}"))));
        withExample(operation(api, "/api/scenes/{name}", PathItem.HttpMethod.GET, "scenes", "getScene",
                "One example scene"), "name", "still-life")
                .responses(new ApiResponses()
                        // written for the default limits, so not necessarily within this server's (components/schemas/Scene)
                        .addApiResponse("200", json("The scene file, in the format of components/schemas/Scene",
                                schema(OBJECT)))
                        .addApiResponse("404", ref("NotFound")));
        operation(api, "/api/scene-schema", PathItem.HttpMethod.GET, "scenes", "getSceneSchema",
                "The scene format as JSON Schema (draft 2020-12), with this server's limits")
                .responses(new ApiResponses().addApiResponse("200", new ApiResponse()
                        .description("The schema (the same as components/schemas/Scene with its definitions)")
                        .content(new Content()
                                .addMediaType("application/schema+json", new MediaType().schema(schema(OBJECT)))
                                .addMediaType("application/json", new MediaType().schema(schema(OBJECT))))));
        withExample(operation(api, "/api/meshes", PathItem.HttpMethod.GET, "scenes", "getMesh",
                "A mesh shipped with the example scenes, as OBJ text"), "file", "meshes/torus-knot.obj")
                .responses(new ApiResponses()
                        .addApiResponse("200", new ApiResponse().description("The OBJ text").content(new Content()
                                .addMediaType("text/plain", new MediaType().schema(schema("{\"type\": \"string\"}")))))
                        .addApiResponse("400", ref("BadRequest"))
                        .addApiResponse("404", ref("NotFound")));

        operation(api, "/api/me", PathItem.HttpMethod.GET, "sign-in", "me",
                "Who is signed in, and whether this server asks callers to sign in")
                .responses(new ApiResponses().addApiResponse("200", json("The caller", schemaRef("Me"))));
        operation(api, "/api/preview/tickets", PathItem.HttpMethod.POST, "sign-in", "issuePreviewTicket",
                "A short-lived, single-use ticket that signs in the live view's WebSocket (/api/preview?ticket=), "
                        + "for a browser, which cannot send headers with it")
                .responses(new ApiResponses()
                        .addApiResponse("200", json("The ticket", schemaRef("PreviewTicket")))
                        .addApiResponse("429", ref("TooManyTickets")));
        AssetContract.describe(api);
        for (Map.Entry<String, PathItem> path : api.getPaths().entrySet()) {
            if (path.getKey().startsWith("/api/")) {
                path.getValue().readOperations().forEach(op -> op.getResponses().addApiResponse("401", ref("Unauthorized")));
            }
        }

        api.path("/actuator/health", new PathItem().get(new Operation().tags(List.of("system"))
                .operationId("health").summary("Whether the service is up")
                .responses(new ApiResponses()
                        .addApiResponse("200", health("Up"))
                        .addApiResponse("503", health("Down or out of service")))));
    }

    private static final String OBJECT = "{\"type\": \"object\"}";
    private static final String BEARER = "bearer";

    private static void components(OpenAPI api, SceneLimits limits) {
        if (api.getComponents() == null) {
            api.components(new Components());
        }
        Components c = api.getComponents();
        if (c.getSchemas() != null) {
            c.getSchemas().remove("SseEmitter"); // springdoc's view of the events endpoint's return type
        }
        ApiSchemas.sceneComponents(limits).forEach((name, schema) -> c.addSchemas(name, convert(schema)));
        c.addSchemas("Problem", schema(ApiSchemas.PROBLEM));
        c.addSchemas("FieldError", schema(ApiSchemas.FIELD_ERROR));
        c.addSchemas("InvalidSceneProblem", schema(ApiSchemas.INVALID_SCENE_PROBLEM));
        c.addSchemas("JobStatus", schema(ApiSchemas.JOB_STATUS));
        c.addSchemas("TileEvent", schema(ApiSchemas.TILE_EVENT));
        c.addSchemas("JobEvent", schema(ApiSchemas.JOB_EVENT));
        c.addSchemas("SceneSummary", schema(ApiSchemas.SCENE_SUMMARY));
        c.addSchemas("Health", schema(ApiSchemas.HEALTH));
        c.addSchemas("Me", schema(ApiSchemas.ME));
        c.addSchemas("PreviewTicket", schema(ApiSchemas.PREVIEW_TICKET));
        c.addSecuritySchemes(BEARER, new SecurityScheme().type(SecurityScheme.Type.HTTP).scheme("bearer")
                .description("With sign-in on: an API key (studio.security.api-keys) or a JWT the server trusts "
                        + "(spring.security.oauth2.resourceserver.jwt.*); its name or sub is the principal"));

        c.addHeaders("RetryAfter", new Header().required(true).description("Seconds to wait before trying again")
                .schema(schema("{\"type\": \"integer\", \"minimum\": 1}")));
        c.addHeaders("Location", new Header().required(true).description("The job's URL, /api/jobs/{id}")
                .schema(schema("{\"type\": \"string\", \"pattern\": \"^/api/jobs/[A-Za-z0-9-]+$\"}")));

        c.addResponses("InvalidScene", problem("The scene is invalid; `errors` names each bad field", "InvalidSceneProblem"));
        c.addResponses("BodyTooLarge", problem("The body is over this server's limit (studio.limits.max-body-bytes), "
                + "or reading it and building its meshes needs more than all of the render memory (studio.render-memory)",
                "Problem"));
        c.addResponses("NotJson", problem("The body is not sent as JSON: its Content-Type is missing or another "
                + "type (text/plain, form data, XML); nothing was read or rendered", "Problem")
                .addHeaderObject("Accept", new Header().required(true).description("The media types a scene is taken as: "
                        + SceneMediaTypes.JSON + ", " + SceneMediaTypes.JSON_SUFFIXED)
                        .schema(schema("{\"type\": \"string\"}"))));
        c.addResponses("BodyTooSlow", problem("The body came too slowly: after studio.limits.body-grace it must keep "
                + "coming at studio.limits.min-body-rate a second on average", "Problem"));
        c.addResponses("RenderTimeExceeded", problem("The render ran longer than this server's time budget "
                + "(studio.limits.max-render-time) and was stopped", "Problem"));
        c.addResponses("RenderBusy", problem("Every render slot is busy (studio.concurrent-renders), the memory for "
                + "reading the body or for the render is taken (studio.render-memory), the server is shutting down, "
                + "or it gave up waiting for the render (its time budget and a minute to encode the image)", "Problem")
                .addHeaderObject("Retry-After", headerRef("RetryAfter")));
        c.addResponses("MemoryBusy", problem("The memory for reading the body and building its meshes is taken by "
                + "other requests (studio.render-memory)", "Problem")
                .addHeaderObject("Retry-After", headerRef("RetryAfter")));
        c.addResponses("QueueFull", problem("The job queue is full (studio.jobs.queue), the principal has as many "
                + "jobs queued or running as one may (studio.security.max-jobs-per-principal, with sign-in on), the "
                + "render memory is taken by other jobs, or the server is shutting down", "Problem")
                .addHeaderObject("Retry-After", headerRef("RetryAfter")));
        c.addResponses("JobNotFound", problem("No job has that id (it never existed, it expired, or it is another "
                + "principal's)", "Problem"));
        c.addResponses("Unauthorized", problem("Sign-in is on and the request sent no API key or token, or one "
                + "that is unknown, expired or forged", "Problem")
                .addHeaderObject("WWW-Authenticate", new Header().required(true)
                        .description("Bearer; with error=\"invalid_token\" when a token was sent and refused")
                        .schema(schema("{\"type\": \"string\", \"pattern\": \"^Bearer\"}"))));
        c.addResponses("TooManyTickets", problem("The principal holds as many unused tickets as it may "
                + "(studio.security.max-tickets-per-principal), or the server does", "Problem")
                .addHeaderObject("Retry-After", headerRef("RetryAfter")));
        c.addResponses("JobNotDone", problem("The job is not done (queued, running, failed or cancelled)", "Problem"));
        c.addResponses("NotFound", problem("No such resource", "Problem"));
        c.addResponses("BadRequest", problem("A parameter is missing or malformed", "Problem"));
    }

    /** The operation springdoc found in the controllers, with its tag, id and summary set. */
    static Operation operation(OpenAPI api, String path, PathItem.HttpMethod method, String tag, String id,
                                       String summary) {
        PathItem item = api.getPaths() != null ? api.getPaths().get(path) : null;
        Operation operation = item != null ? item.readOperationsMap().get(method) : null;
        if (operation == null) {
            throw new IllegalStateException("the API contract describes " + method + " " + path
                    + ", which no controller serves");
        }
        return operation.tags(List.of(tag)).operationId(id).summary(summary);
    }

    /** The operation, its parameter {@code name} given an example value (one that exists). */
    private static Operation withExample(Operation operation, String name, String value) {
        List<Parameter> parameters = operation.getParameters() != null ? operation.getParameters() : List.of();
        parameters.stream().filter(p -> p.getName().equals(name)).findFirst()
                .orElseThrow(() -> new IllegalStateException("no parameter " + name + " in " + operation.getOperationId()))
                .example(value);
        return operation;
    }

    private static RequestBody sceneBody() {
        return new RequestBody().required(true).description("A scene (see components/schemas/Scene)")
                .content(new Content().addMediaType(SceneMediaTypes.JSON, new MediaType().schema(schemaRef("Scene"))
                        .example(json(ApiSchemas.EXAMPLE_SCENE))));
    }

    private static ApiResponse image(String description) {
        Map<String, Header> headers = Map.of(
                "Content-Disposition", header("attachment; filename=\"NAME.png\" (the scene's name, sanitised)",
                        "{\"type\": \"string\", \"pattern\": \"^attachment; \"}"),
                "X-Render-Millis", header("Render time in milliseconds", "{\"type\": \"integer\", \"minimum\": 0}"),
                "X-Rays-Per-Second", header("Rays traced per second", "{\"type\": \"integer\", \"minimum\": 0}"),
                "X-Image-Size", header("WIDTHxHEIGHT in pixels", "{\"type\": \"string\", \"pattern\": \"^[0-9]+x[0-9]+$\"}"));
        return new ApiResponse().description(description).headers(new TreeMap<>(headers)).content(new Content()
                .addMediaType("image/png", new MediaType())
                .addMediaType("image/jpeg", new MediaType()));
    }

    /** The operation on the job a 202 has just started: its id comes from the response body. */
    private static Link jobLink(String operationId) {
        return new Link().operationId(operationId).parameters("id", "$response.body#/id");
    }

    private static ApiResponse jobStatus(String description) {
        return json(description, schemaRef("JobStatus"));
    }

    private static ApiResponse health(String description) {
        Schema<?> health = schemaRef("Health");
        return new ApiResponse().description(description).content(new Content()
                .addMediaType("application/vnd.spring-boot.actuator.v3+json", new MediaType().schema(health))
                .addMediaType("application/json", new MediaType().schema(health)));
    }

    static ApiResponse json(String description, Schema<?> schema) {
        return new ApiResponse().description(description)
                .content(new Content().addMediaType("application/json", new MediaType().schema(schema)));
    }

    static ApiResponse problem(String description, String schemaName) {
        return new ApiResponse().description(description)
                .content(new Content().addMediaType(PROBLEM_JSON, new MediaType().schema(schemaRef(schemaName))));
    }

    static ApiResponse ref(String response) {
        return new ApiResponse().$ref("#/components/responses/" + response);
    }

    static Header headerRef(String header) {
        return new Header().$ref("#/components/headers/" + header);
    }

    private static Header header(String description, String schema) {
        return new Header().required(true).description(description).schema(schema(schema));
    }

    private static Object json(String json) {
        try {
            return Json31.mapper().readValue(json, Map.class);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("bad JSON in the API contract: " + json, e);
        }
    }

    static Schema<?> schemaRef(String name) {
        return schema("{\"$ref\": \"" + ApiSchemas.REF + name + "\"}");
    }

    static Schema<?> schema(String json) {
        return convert(json(json));
    }

    /** A JSON Schema map as swagger's model, read the OpenAPI 3.1 way (type arrays, const, numeric exclusive bounds). */
    private static Schema<?> convert(Object schema) {
        return Json31.mapper().convertValue(schema, Schema.class);
    }
}

package studio.server.api;

import static studio.server.api.OpenApiContract.headerRef;
import static studio.server.api.OpenApiContract.json;
import static studio.server.api.OpenApiContract.operation;
import static studio.server.api.OpenApiContract.problem;
import static studio.server.api.OpenApiContract.ref;
import static studio.server.api.OpenApiContract.schema;
import static studio.server.api.OpenApiContract.schemaRef;

import java.util.List;

import io.swagger.v3.oas.models.OpenAPI;
import io.swagger.v3.oas.models.PathItem;
import io.swagger.v3.oas.models.headers.Header;
import io.swagger.v3.oas.models.media.Content;
import io.swagger.v3.oas.models.media.MediaType;
import io.swagger.v3.oas.models.parameters.RequestBody;
import io.swagger.v3.oas.models.responses.ApiResponse;
import io.swagger.v3.oas.models.responses.ApiResponses;

/** The asset endpoints in the OpenAPI document (POST, HEAD and GET /api/assets; docs/api.md). */
final class AssetContract {

    static final List<String> MEDIA_TYPES = List.of("model/obj", "image/png", "image/jpeg", "model/gltf-binary",
            "model/gltf+json");
    private static final String ID = "^sha256-[0-9a-f]{64}$";
    static final String ASSET = """
            {
              "type": "object",
              "description": "An asset as kept: its id (sha256- and the hex SHA-256 of its bytes), size and media type.",
              "properties": {
                "id": { "type": "string", "pattern": "%s" },
                "bytes": { "type": "integer", "minimum": 1 },
                "mediaType": { "type": "string", "enum": ["model/obj", "image/png", "image/jpeg", "model/gltf-binary", "model/gltf+json"] }
              },
              "required": ["id", "bytes", "mediaType"],
              "additionalProperties": false
            }
            """.formatted(ID);

    private AssetContract() {
    }

    static void describe(OpenAPI api) {
        api.getComponents().addSchemas("Asset", schema(ASSET));
        Content bytes = new Content();
        MEDIA_TYPES.forEach(type -> bytes.addMediaType(type, new MediaType()
                .schema(schema("{\"type\": \"string\", \"contentMediaType\": \"" + type + "\"}"))));
        operation(api, "/api/assets", PathItem.HttpMethod.POST, "assets", "uploadAsset",
                "Keep bytes (an OBJ mesh, a PNG or JPEG image, a glTF model) by the SHA-256 of their content")
                .requestBody(new RequestBody().required(true).content(bytes)
                        .description("The raw bytes; Content-Type says what they are, and they are checked to be so"))
                .responses(new ApiResponses()
                        .addApiResponse("201", json("Kept; Location names the asset", schemaRef("Asset"))
                                .addHeaderObject("Location", new Header().required(true).description("/api/assets/{id}")
                                        .schema(schema("{\"type\": \"string\", \"pattern\": \"^/api/assets/sha256-[0-9a-f]{64}$\"}"))))
                        .addApiResponse("200", json("Kept already: the same bytes were uploaded before", schemaRef("Asset")))
                        .addApiResponse("400", problem("The bytes are not what their Content-Type says, or break a "
                                + "limit of their kind (an image's pixels, an OBJ's triangles); nothing was kept", "Problem"))
                        .addApiResponse("408", ref("BodyTooSlow"))
                        .addApiResponse("413", problem("The asset is over studio.assets.max-bytes (or the body over "
                                + "studio.limits.max-body-bytes)", "Problem"))
                        .addApiResponse("415", problem("The Content-Type is none of " + String.join(", ", MEDIA_TYPES),
                                "Problem"))
                        .addApiResponse("503", problem("No room for the asset now (the memory is held by renders); "
                                + "try again after Retry-After", "Problem").addHeaderObject("Retry-After", headerRef("RetryAfter"))));
        operation(api, "/api/assets/{id}", PathItem.HttpMethod.HEAD, "assets", "hasAsset",
                "Whether the server keeps an asset (upload it if not)")
                .responses(new ApiResponses()
                        .addApiResponse("200", new ApiResponse().description("Kept"))
                        .addApiResponse("400", new ApiResponse().description("Not an asset id"))
                        .addApiResponse("404", new ApiResponse().description("Not kept")));
        Content stored = new Content();
        MEDIA_TYPES.forEach(type -> stored.addMediaType(type, new MediaType()));
        operation(api, "/api/assets/{id}", PathItem.HttpMethod.GET, "assets", "getAsset",
                "An asset's bytes, with the media type it was uploaded as; immutable, its ETag is its id")
                .responses(new ApiResponses()
                        .addApiResponse("200", new ApiResponse().description("The bytes").content(stored)
                                .addHeaderObject("ETag", new Header().required(true).description("The id, quoted")
                                        .schema(schema("{\"type\": \"string\"}"))))
                        .addApiResponse("304", new ApiResponse().description("Not modified (If-None-Match named it)"))
                        .addApiResponse("400", problem("Not an asset id", "Problem"))
                        .addApiResponse("404", problem("Not kept: upload it", "Problem")));
    }
}

package studio.server.asset;

import static org.hamcrest.Matchers.containsString;
import static org.mockito.ArgumentMatchers.any;
import static org.mockito.ArgumentMatchers.argThat;
import static org.mockito.ArgumentMatchers.eq;
import static org.mockito.BDDMockito.given;
import static org.mockito.Mockito.mock;
import static org.mockito.Mockito.never;
import static org.mockito.Mockito.verify;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.head;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.header;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.TestConfiguration;
import org.springframework.boot.webmvc.test.autoconfigure.WebMvcTest;
import org.springframework.context.annotation.Bean;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.test.context.bean.override.mockito.MockitoBean;
import org.springframework.test.web.servlet.MockMvc;

import studio.server.scene.compiling.MeshAssets;

/**
 * The assets endpoints' mapping onto HTTP, with the store and the checks mocked: 201 and Location for
 * a new asset, 200 for a kept one, ETag and immutable caching on reads, and each refusal a problem.
 * What the checks and the store themselves refuse is AssetApiTest's, through the whole application.
 */
@WebMvcTest(AssetController.class)
class AssetControllerTest {

    /** The largest asset this slice's controller keeps. */
    private static final long MAX_BYTES = 16;
    private static final byte[] OBJ = "v 0 0 0\n".getBytes();
    private static final String ID = AssetIds.of(OBJ);

    @Autowired
    MockMvc mvc;

    @MockitoBean
    AssetStore store;

    @MockitoBean
    AssetChecks checks;

    @TestConfiguration
    static class Limits {
        @Bean
        AssetLimits assetLimits() {
            return new AssetLimits(MAX_BYTES, 1024);
        }
    }

    @BeforeEach
    void meshes() {
        given(store.meshes()).willReturn(mock(MeshAssets.class));
    }

    @Test
    void newAssetAnswers201WithItsLocationAndTheChecksWarnings() throws Exception {
        given(checks.check(eq(AssetType.OBJ), eq(OBJ), any(), any())).willReturn(List.of("a warning"));
        given(store.put(any())).willReturn(true);
        mvc.perform(post("/api/assets").contentType("model/obj").content(OBJ))
                .andExpect(status().isCreated())
                .andExpect(header().string(HttpHeaders.LOCATION, "/api/assets/" + ID))
                .andExpect(content().contentType(MediaType.APPLICATION_JSON))
                .andExpect(jsonPath("$.id").value(ID))
                .andExpect(jsonPath("$.bytes").value(OBJ.length))
                .andExpect(jsonPath("$.mediaType").value("model/obj"))
                .andExpect(jsonPath("$.warnings[0]").value("a warning"));
        verify(store).put(argThat(asset -> asset.id().equals(ID) && asset.type() == AssetType.OBJ
                && Arrays.equals(asset.bytes(), OBJ)));
    }

    @Test
    void assetKeptAlreadyAnswers200WithoutLocationAndIsNotKeptAgain() throws Exception {
        given(checks.check(any(), any(), any(), any())).willReturn(List.of());
        given(store.get(ID)).willReturn(Asset.of(AssetType.OBJ, OBJ));
        mvc.perform(post("/api/assets").contentType("model/obj").content(OBJ))
                .andExpect(status().isOk())
                .andExpect(header().doesNotExist(HttpHeaders.LOCATION))
                .andExpect(jsonPath("$.id").value(ID))
                .andExpect(jsonPath("$.warnings").isEmpty());
        verify(store, never()).put(any());
    }

    @Test
    void assetAnotherRequestKeptMeanwhileAnswers200WithoutLocation() throws Exception {
        given(checks.check(any(), any(), any(), any())).willReturn(List.of());
        given(store.put(any())).willReturn(false);
        mvc.perform(post("/api/assets").contentType("model/obj").content(OBJ))
                .andExpect(status().isOk())
                .andExpect(header().doesNotExist(HttpHeaders.LOCATION))
                .andExpect(jsonPath("$.id").value(ID));
    }

    @Test
    void unsupportedMediaTypeGives415NamingTheTypesToSendAndChecksNothing() throws Exception {
        mvc.perform(post("/api/assets").contentType(MediaType.TEXT_PLAIN).content(OBJ))
                .andExpect(status().isUnsupportedMediaType())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(415))
                .andExpect(jsonPath("$.detail").value(containsString("model/obj")))
                .andExpect(jsonPath("$.detail").value(containsString("this request's is 'text/plain")));
        mvc.perform(post("/api/assets").content(OBJ))
                .andExpect(status().isUnsupportedMediaType())
                .andExpect(jsonPath("$.detail").value(containsString("missing")));
        verify(checks, never()).check(any(), any(), any(), any());
        verify(store, never()).put(any());
    }

    @Test
    void assetOverTheSizeLimitGives413NamingTheLimitAndChecksNothing() throws Exception {
        mvc.perform(post("/api/assets").contentType("model/obj").content(new byte[(int) MAX_BYTES + 1]))
                .andExpect(status().isContentTooLarge())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(413))
                .andExpect(jsonPath("$.detail").value(containsString("at most " + MAX_BYTES + " bytes")))
                .andExpect(jsonPath("$.detail").value(containsString("studio.assets.max-bytes")));
        verify(checks, never()).check(any(), any(), any(), any());
        verify(store, never()).put(any());
    }

    @Test
    void assetTheChecksRefuseGives400AndIsNotKept() throws Exception {
        given(checks.check(any(), any(), any(), any()))
                .willThrow(AssetRefusedException.invalid(AssetType.OBJ, "line 1: not a number"));
        mvc.perform(post("/api/assets").contentType("model/obj").content(OBJ))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(400))
                .andExpect(jsonPath("$.title").value("Invalid asset"))
                .andExpect(jsonPath("$.detail").value(containsString("line 1: not a number")));
        verify(store, never()).put(any());
    }

    @Test
    void emptyBodyIsCheckedAsNoBytes() throws Exception {
        given(checks.check(any(), any(), any(), any()))
                .willThrow(AssetRefusedException.invalid(AssetType.OBJ, "the body is empty"));
        mvc.perform(post("/api/assets").contentType("model/obj"))
                .andExpect(status().isBadRequest());
        verify(checks).check(eq(AssetType.OBJ), eq(new byte[0]), any(), any());
    }

    @Test
    void fullStoreGives503WithRetryAfter() throws Exception {
        given(checks.check(any(), any(), any(), any())).willReturn(List.of());
        given(store.put(any())).willThrow(AssetRefusedException.full(OBJ.length));
        mvc.perform(post("/api/assets").contentType("model/obj").content(OBJ))
                .andExpect(status().isServiceUnavailable())
                .andExpect(header().string(HttpHeaders.RETRY_AFTER, "5"))
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(503));
    }

    @Test
    void headOfAKeptAssetGivesItsTypeLengthAndIdAsETag() throws Exception {
        given(store.get(ID)).willReturn(Asset.of(AssetType.OBJ, OBJ));
        mvc.perform(head("/api/assets/" + ID))
                .andExpect(status().isOk())
                .andExpect(header().string(HttpHeaders.CONTENT_TYPE, "model/obj"))
                .andExpect(header().string(HttpHeaders.CONTENT_LENGTH, String.valueOf(OBJ.length)))
                .andExpect(header().string(HttpHeaders.ETAG, "\"" + ID + "\""))
                .andExpect(header().string(HttpHeaders.CACHE_CONTROL, containsString("immutable")));
    }

    @Test
    void headOfAnUnknownAssetGives404AndOfAMalformedId400() throws Exception {
        mvc.perform(head("/api/assets/" + ID)).andExpect(status().isNotFound());
        mvc.perform(head("/api/assets/sha256-ABC")).andExpect(status().isBadRequest());
        verify(store, never()).get("sha256-ABC");
    }

    @Test
    void getReturnsTheBytesImmutablyForAYearWithTheIdAsETag() throws Exception {
        given(store.get(ID)).willReturn(Asset.of(AssetType.OBJ, OBJ));
        mvc.perform(get("/api/assets/" + ID))
                .andExpect(status().isOk())
                .andExpect(content().contentType("model/obj"))
                .andExpect(content().bytes(OBJ))
                .andExpect(header().string(HttpHeaders.ETAG, "\"" + ID + "\""))
                .andExpect(header().string(HttpHeaders.CACHE_CONTROL, "max-age=31536000, immutable"));
    }

    @Test
    void getWithTheETagAnswers304WithoutTheBytes() throws Exception {
        given(store.get(ID)).willReturn(Asset.of(AssetType.OBJ, OBJ));
        mvc.perform(get("/api/assets/" + ID).header(HttpHeaders.IF_NONE_MATCH, "\"" + ID + "\""))
                .andExpect(status().isNotModified())
                .andExpect(header().string(HttpHeaders.ETAG, "\"" + ID + "\""))
                .andExpect(content().bytes(new byte[0]));
    }

    @Test
    void getOfAnUnknownAssetGives404ProblemNamingIt() throws Exception {
        mvc.perform(get("/api/assets/" + ID))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(404))
                .andExpect(jsonPath("$.detail").value(containsString(ID)));
    }

    @Test
    void getOfAMalformedIdGives400ProblemSayingWhatAnIdIs() throws Exception {
        mvc.perform(get("/api/assets/sha256-" + "A".repeat(64)))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(400))
                .andExpect(jsonPath("$.detail").value(containsString("64 lowercase hex digits")));
    }

    @Test
    void unknownPathGives404Problem() throws Exception {
        mvc.perform(get("/api/asset/" + ID))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(404));
        verify(store, never()).get(any());
    }
}

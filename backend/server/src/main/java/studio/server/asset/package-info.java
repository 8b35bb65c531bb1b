/**
 * Assets by content hash: bytes a scene names by id ({@code sha256-<hex>}) instead of carrying them
 * (POST, HEAD and GET /api/assets), checked before they are kept, kept within the memory budget.
 */
package studio.server.asset;

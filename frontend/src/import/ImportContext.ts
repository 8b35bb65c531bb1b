/** The editor's import (see `useImport.ts`) for components deep in the inspector: "Pick image…". */
import { createContext, useContext } from 'react';

export const ImportContext = createContext<((files: File[]) => void) | null>(null);

/** The import, or null outside the editor (no pick buttons then). */
export function useImportFiles(): ((files: File[]) => void) | null {
  return useContext(ImportContext);
}

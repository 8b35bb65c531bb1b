/** The editor's import (see `useImport.ts`) for components deep in the inspector: "Pick image…". */
import { createContext, useContext } from 'react';
import type { ImportOptions } from './importFile';

export type ImportFiles = (files: File[], options?: ImportOptions) => void;

export const ImportContext = createContext<ImportFiles | null>(null);

/** The import, or null outside the editor (no pick buttons then). */
export function useImportFiles(): ImportFiles | null {
  return useContext(ImportContext);
}

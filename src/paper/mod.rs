//! The paper's formulas exactly as printed, tagged by equation number (issue 4).

pub(super) fn claims(_out: &mut Vec<super::Claim>) {}
